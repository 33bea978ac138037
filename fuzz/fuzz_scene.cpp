// Fuzz target: the scene reader. Any input must be read or refused with a
// message naming the file; a scene that is read must read back the same from
// the JSON it writes (the editor's Save Scene relies on it).
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <nlohmann/json.hpp>
#include <string>
#include <variant>

#include "core/run/scene.hpp"
#include "fuzz/fuzz_support.hpp"

namespace {

template <int D>
void require_round_trip(const amls::Scene<D>& scene, const std::string& path) {
  const nlohmann::json written = amls::to_json(scene);
  const amls::AnyScene again = amls::scene_from_json(written, path);
  const nlohmann::json rewritten = amls::to_json(std::get<amls::Scene<D>>(again));
  if (written == rewritten) return;
  std::fprintf(stderr, "the scene changed on a round trip:\n%s\n%s\n", written.dump().c_str(), rewritten.dump().c_str());
  std::abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = amls::fuzz::input_file(data, size, ".json");
  amls::AnyScene scene;
  try {
    scene = amls::read_scene(path);
  } catch (const std::exception& e) {
    amls::fuzz::require_names_file(e.what(), path);
    return 0;
  }
  std::visit([&](const auto& s) { require_round_trip(s, path); }, scene);
  return 0;
}
