#pragma once
// Which headless OpenGL to use, decided without GL: the backends in the order they are
// tried, and the EGL devices in the order they are tried. render/offscreen_context.cpp
// opens them; keeping the decisions here makes them testable on any machine.
//
// The order, unless a backend is forced:
//   1. egl-device: EGL_EXT_platform_device on each device eglQueryDevicesEXT lists,
//      hardware first (in the order listed), Mesa's software device (llvmpipe) last;
//   2. egl-surfaceless: EGL_MESA_platform_surfaceless (Mesa picks the GPU or llvmpipe);
//   3. osmesa: Mesa's OSMesa (llvmpipe), where the build has it (Mesa dropped it in 25.1).
// The environment (or a program's options, which take precedence) can force one:
//   AMLS_GL_BACKEND=egl-device|egl-surfaceless|osmesa   (auto or empty: the order above)
//   AMLS_EGL_DEVICE=N   the N-th device eglQueryDevicesEXT lists, from 0 (implies egl-device)
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace amls {

enum class HeadlessBackend { egl_device, egl_surfaceless, osmesa };

inline constexpr const char* kGlBackendVariable = "AMLS_GL_BACKEND";
inline constexpr const char* kEglDeviceVariable = "AMLS_EGL_DEVICE";

// "egl-device", "egl-surfaceless", "osmesa".
const char* to_string(HeadlessBackend backend);
// "auto" and "" mean none; any other name not above throws std::invalid_argument naming
// `source` (the variable or option it came from) and the names allowed.
std::optional<HeadlessBackend> headless_backend_from_string(std::string_view name, std::string_view source);
// An EGL device index: digits only, 0 to 1023. Throws std::invalid_argument naming `source` otherwise.
int egl_device_index_from_string(std::string_view text, std::string_view source);

struct HeadlessGlChoice {
  std::optional<HeadlessBackend> backend;  // none: each backend in turn
  std::optional<int> egl_device;           // none: each EGL device in turn
};

// The choice AMLS_GL_BACKEND and AMLS_EGL_DEVICE make (unset or empty: none). Throws
// std::invalid_argument for a bad value, naming the variable.
HeadlessGlChoice headless_gl_choice_from_environment();
// The same from the variables' values (nullptr: unset).
HeadlessGlChoice headless_gl_choice_from(const char* backend_value, const char* device_value);

// The backends to try, in order, among those `built` (in this build). Throws
// std::invalid_argument when an EGL device is chosen with a backend other than egl-device,
// and std::runtime_error when the backend forced is not built or nothing is.
std::vector<HeadlessBackend> headless_backend_order(const HeadlessGlChoice& choice,
                                                    const std::vector<HeadlessBackend>& built);

// Whether the space-separated extension list `extensions` has `name` (a whole word).
bool has_extension(std::string_view extensions, std::string_view name);
// A device whose extension string has EGL_MESA_device_software: Mesa's llvmpipe.
bool is_software_egl_device(std::string_view device_extensions);

// The EGL devices to try, as indices into `device_extensions` (each device's extension
// string, in eglQueryDevicesEXT's order): hardware devices first in that order, software
// devices last; or only `chosen`. Throws std::invalid_argument when `chosen` is not an index
// of the list, naming how many devices there are.
std::vector<int> egl_device_order(const std::vector<std::string>& device_extensions, std::optional<int> chosen);

// What a headless context turned out to be, for programs to report.
struct HeadlessGlInfo {
  HeadlessBackend backend = HeadlessBackend::egl_device;
  std::string device;      // egl-device: which one, e.g. "1 of 2, software (EGL_MESA_device_software)"; else empty
  std::string gl_version;  // GL_VERSION
  std::string gl_renderer;  // GL_RENDERER
  std::vector<std::string> failures;  // what was tried before, each "backend: why it failed"

  // One line: "egl-device 1 of 2, software (...); OpenGL 4.5 (Core Profile) Mesa 22.3.6; llvmpipe (...)".
  std::string summary() const;
};

}  // namespace amls
