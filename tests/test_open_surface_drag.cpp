#include <doctest/doctest.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/run/scene_run.hpp"
#include "temp_dir.hpp"

using namespace amls;
using amls::test::TempDir;

namespace {

// A sphere of radius 0.49 cut at z = 0.375 (an open cap, like CGAL's
// half.xyz but sampled densely enough to be its own exact shape: its points
// are the tracers), written with outward normals to `path`.
void write_open_cap(const std::string& path, std::size_t sphere_points) {
  std::FILE* f = std::fopen(path.c_str(), "w");
  REQUIRE(f != nullptr);
  const double radius = 0.49, golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (std::size_t i = 0; i < sphere_points; ++i) {
    const double z = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(sphere_points);
    const double r = std::sqrt(1.0 - z * z), a = golden * static_cast<double>(i);
    if (radius * z > 0.375) continue;
    std::fprintf(f, "%.12g %.12g %.12g %.12g %.12g %.12g\n", radius * r * std::cos(a), radius * r * std::sin(a),
                 radius * z, r * std::cos(a), r * std::sin(a), z);
  }
  std::fclose(f);
}

// The cap's bottom pulled a quarter of its size down in 30 steps, against
// four handles on its equator, as a user drags a scan.
Scene<3> cap_drag(const std::string& file) {
  Scene<3> scene;
  scene.shape.type = ShapeType::file;
  scene.shape.file = scene.shape.resolved_file = file;
  scene.grid_spacing = 0.06;
  scene.widen_support = true;
  const double e = 0.49;
  std::vector<Vec<3>> start{Vec<3>(0, 0, -e), Vec<3>(e, 0, 0), Vec<3>(-e, 0, 0), Vec<3>(0, e, 0), Vec<3>(0, -e, 0)};
  std::vector<Vec<3>> pulled = start;
  pulled[0].z() -= 0.25;
  scene.history.begin_stage(start);
  scene.history.add_target(pulled, 30);
  return scene;
}

}  // namespace

TEST_CASE("an open cap dragged 30 steps stays an open cap: within 0.25 h of its exact shape, no hole, always and local") {
  TempDir dir;
  const std::string file = dir.file("cap.xyz");
  write_open_cap(file, 8000);
  const Scene<3> scene = cap_drag(file);
  for (const char* policy : {"always", "local"}) {
    CAPTURE(policy);
    SceneRunOptions options;
    options.threads = 2;
    options.policy = ResamplePolicy::parse(policy);
    const SceneRunReport r = run_scene<3>(scene, options);
    CHECK_FALSE(r.broken);
    CHECK(r.steps == 30);
    // Closed into an egg, the top would lie a cap's opening (over 5 h) from the exact shape.
    CHECK(r.distance_to_exact_h.mean <= 0.25);
    CHECK(r.distance_to_exact_h.max <= 2.0);
    CHECK(r.exact_to_points_h.max <= 1.5);
  }
}
