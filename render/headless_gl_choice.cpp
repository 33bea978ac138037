#include "render/headless_gl_choice.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>

namespace amls {

namespace {

constexpr HeadlessBackend kAllBackends[] = {HeadlessBackend::egl_device, HeadlessBackend::egl_surfaceless,
                                            HeadlessBackend::osmesa};
constexpr int kMaxEglDeviceIndex = 1023;

std::string quoted(std::string_view text) { return "'" + std::string(text) + "'"; }

}  // namespace

const char* to_string(HeadlessBackend backend) {
  switch (backend) {
    case HeadlessBackend::egl_device:
      return "egl-device";
    case HeadlessBackend::egl_surfaceless:
      return "egl-surfaceless";
    case HeadlessBackend::osmesa:
      return "osmesa";
  }
  return "?";
}

std::optional<HeadlessBackend> headless_backend_from_string(std::string_view name, std::string_view source) {
  if (name.empty() || name == "auto") return std::nullopt;
  for (HeadlessBackend backend : kAllBackends)
    if (name == to_string(backend)) return backend;
  throw std::invalid_argument(std::string(source) + ": " + quoted(name) +
                              " is not a headless OpenGL backend; use auto, egl-device, egl-surfaceless or osmesa");
}

int egl_device_index_from_string(std::string_view text, std::string_view source) {
  const bool digits = !text.empty() && text.size() <= 4 &&
                      std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; });
  const int index = digits ? std::atoi(std::string(text).c_str()) : -1;
  if (index < 0 || index > kMaxEglDeviceIndex)
    throw std::invalid_argument(std::string(source) + ": " + quoted(text) +
                                " is not an EGL device index (0, 1, ... as eglQueryDevicesEXT lists them, at most " +
                                std::to_string(kMaxEglDeviceIndex) + ")");
  return index;
}

HeadlessGlChoice headless_gl_choice_from(const char* backend_value, const char* device_value) {
  HeadlessGlChoice choice;
  if (backend_value != nullptr) choice.backend = headless_backend_from_string(backend_value, kGlBackendVariable);
  if (device_value != nullptr && *device_value != '\0')
    choice.egl_device = egl_device_index_from_string(device_value, kEglDeviceVariable);
  return choice;
}

HeadlessGlChoice headless_gl_choice_from_environment() {
  return headless_gl_choice_from(std::getenv(kGlBackendVariable), std::getenv(kEglDeviceVariable));
}

std::vector<HeadlessBackend> headless_backend_order(const HeadlessGlChoice& choice,
                                                    const std::vector<HeadlessBackend>& built) {
  auto is_built = [&](HeadlessBackend backend) { return std::find(built.begin(), built.end(), backend) != built.end(); };
  std::optional<HeadlessBackend> forced = choice.backend;
  if (choice.egl_device) {
    if (forced && *forced != HeadlessBackend::egl_device)
      throw std::invalid_argument("EGL device " + std::to_string(*choice.egl_device) +
                                  " was chosen, which needs the egl-device backend, but the backend chosen is " +
                                  to_string(*forced));
    forced = HeadlessBackend::egl_device;
  }
  if (forced) {
    if (!is_built(*forced))
      throw std::runtime_error(std::string("the headless OpenGL backend ") + to_string(*forced) +
                               " was chosen, but this build does not have it" +
                               (*forced == HeadlessBackend::osmesa
                                    ? " (configured with AMLS_WITH_OSMESA=OFF, or libosmesa6-dev was missing)"
                                    : " (configured with AMLS_WITH_EGL=OFF, or libegl-dev was missing)"));
    return {*forced};
  }
  std::vector<HeadlessBackend> order;
  for (HeadlessBackend backend : kAllBackends)
    if (is_built(backend)) order.push_back(backend);
  if (order.empty()) throw std::runtime_error("this build has no headless OpenGL backend (neither EGL nor OSMesa)");
  return order;
}

bool has_extension(std::string_view extensions, std::string_view name) {
  if (name.empty()) return false;
  for (std::size_t at = extensions.find(name); at != std::string_view::npos; at = extensions.find(name, at + 1)) {
    const bool starts_word = at == 0 || extensions[at - 1] == ' ';
    const std::size_t end = at + name.size();
    const bool ends_word = end == extensions.size() || extensions[end] == ' ';
    if (starts_word && ends_word) return true;
  }
  return false;
}

bool is_software_egl_device(std::string_view device_extensions) {
  return has_extension(device_extensions, "EGL_MESA_device_software");
}

std::vector<int> egl_device_order(const std::vector<std::string>& device_extensions, std::optional<int> chosen) {
  const int count = static_cast<int>(device_extensions.size());
  if (chosen) {
    if (*chosen < 0 || *chosen >= count)
      throw std::invalid_argument("EGL device " + std::to_string(*chosen) + " was chosen, but there " +
                                  (count == 1 ? "is 1 EGL device (index 0)"
                                   : count == 0
                                       ? "are no EGL devices"
                                       : "are " + std::to_string(count) + " EGL devices (indices 0 to " +
                                             std::to_string(count - 1) + ")"));
    return {*chosen};
  }
  std::vector<int> order;
  for (int i = 0; i < count; ++i)
    if (!is_software_egl_device(device_extensions[i])) order.push_back(i);
  for (int i = 0; i < count; ++i)
    if (is_software_egl_device(device_extensions[i])) order.push_back(i);
  return order;
}

std::string HeadlessGlInfo::summary() const {
  std::string text = to_string(backend);
  if (!device.empty()) text += " " + device;
  return text + "; OpenGL " + gl_version + "; " + gl_renderer;
}

}  // namespace amls
