// The egl-device kind of headless context: EGL_EXT_platform_device on one of the devices
// eglQueryDevicesEXT lists (EGL_EXT_device_enumeration), GPUs before Mesa's software device.
// Needs no display server, no /dev/dri for the software device, and picks among several GPUs.
#include <vector>

#include "render/egl_context.hpp"

namespace amls {

namespace {

// "0 of 2, /dev/dri/renderD128" or "1 of 2, software (EGL_MESA_device_software)".
std::string device_description(int index, int count, const std::string& extensions, EGLDeviceEXT device,
                               PFNEGLQUERYDEVICESTRINGEXTPROC query_string) {
  std::string text = std::to_string(index) + " of " + std::to_string(count) + ", ";
  if (is_software_egl_device(extensions)) return text + "software (EGL_MESA_device_software)";
  // Only ask for what the device lists: asking for more is an EGL error.
  const char* file = nullptr;
  if (has_extension(extensions, "EGL_EXT_device_drm_render_node"))
    file = query_string(device, EGL_DRM_RENDER_NODE_FILE_EXT);
  if (file == nullptr && has_extension(extensions, "EGL_EXT_device_drm"))
    file = query_string(device, EGL_DRM_DEVICE_FILE_EXT);
  return text + (file ? file : "hardware");
}

// The devices eglQueryDevicesEXT lists, each with its extension string.
struct EglDevices {
  EglDevices() {
    require_egl_client_extensions({"EGL_EXT_device_enumeration", "EGL_EXT_device_query", "EGL_EXT_platform_device"});
    const auto query_devices = egl_function<PFNEGLQUERYDEVICESEXTPROC>("eglQueryDevicesEXT");
    query_string = egl_function<PFNEGLQUERYDEVICESTRINGEXTPROC>("eglQueryDeviceStringEXT");
    EGLint count = 0;
    if (query_devices(0, nullptr, &count) == EGL_FALSE)
      throw std::runtime_error("eglQueryDevicesEXT failed (" + egl_error_text() + ")");
    devices.resize(static_cast<std::size_t>(count));
    if (count > 0 && query_devices(count, devices.data(), &count) == EGL_FALSE)
      throw std::runtime_error("eglQueryDevicesEXT failed (" + egl_error_text() + ")");
    devices.resize(static_cast<std::size_t>(count));
    for (EGLDeviceEXT device : devices) {
      const char* text = query_string(device, EGL_EXTENSIONS);
      extensions.emplace_back(text ? text : "");
    }
  }

  std::vector<EGLDeviceEXT> devices;
  std::vector<std::string> extensions;
  PFNEGLQUERYDEVICESTRINGEXTPROC query_string = nullptr;
};

}  // namespace

std::vector<std::string> list_egl_device_extensions() { return EglDevices().extensions; }

std::unique_ptr<HeadlessGl> open_egl_device(std::optional<int> chosen) {
  const EglDevices listed;
  const int count = static_cast<int>(listed.devices.size());
  const std::vector<std::string>& extensions = listed.extensions;
  const auto& devices = listed.devices;
  const std::vector<int> order = egl_device_order(extensions, chosen);  // a bad index: std::invalid_argument
  if (order.empty()) throw std::runtime_error("eglQueryDevicesEXT lists no devices");
  std::string failures;
  for (int i : order) {
    const auto at = static_cast<std::size_t>(i);
    const std::string description = device_description(i, count, extensions[at], devices[at], listed.query_string);
    try {
      EGLDisplay display = egl_platform_display(EGL_PLATFORM_DEVICE_EXT, devices[at], "EGL_EXT_platform_device");
      return make_egl_context(display, HeadlessBackend::egl_device, description);
    } catch (const std::runtime_error& e) {
      failures += (failures.empty() ? "" : "; ") + std::string("device ") + description + ": " + e.what();
    }
  }
  throw std::runtime_error(failures);
}

}  // namespace amls
