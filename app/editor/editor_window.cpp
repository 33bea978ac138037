#include "app/editor/editor_window.hpp"

// glad before anything that includes GL; GLFW without its own GL header.
#include "render/gl.hpp"
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <imgui_impl_glfw.h>
#include <imgui_impl_opengl3.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <utility>

namespace amls::editor {

namespace {

std::string glfw_error() {
  const char* description = nullptr;
  glfwGetError(&description);
  return description ? description : "unknown GLFW error";
}

EditorWindow* owner(GLFWwindow* window) { return static_cast<EditorWindow*>(glfwGetWindowUserPointer(window)); }

glm::vec2 cursor_of(GLFWwindow* window) {
  double x = 0.0, y = 0.0;
  glfwGetCursorPos(window, &x, &y);
  return {static_cast<float>(x), static_cast<float>(y)};
}

constexpr const char* kFonts[] = {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf",
                                  "/usr/share/fonts/TTF/DejaVuSans.ttf"};

}  // namespace

// The callbacks reach the window through GLFW's user pointer; ImGui's backend,
// installed after them, calls them on (it chains to callbacks set before it).
//
// Buttons, wheel turns and keys carry the cursor where the events before them
// left it, not glfwGetCursorPos(): on X11 that asks for the pointer's position
// now, so after a slow frame a press followed by a quick move would be seen
// where the move ended (a drag from a handle would orbit instead).
struct WindowCallbacks {
  static void button(GLFWwindow* w, int button, int action, int mods) {
    EditorWindow* self = owner(w);
    self->events_.push_back({InputEvent::Type::button, button, action, mods, self->cursor_, {}});
  }
  static void cursor(GLFWwindow* w, double x, double y) {
    EditorWindow* self = owner(w);
    self->cursor_ = {static_cast<float>(x), static_cast<float>(y)};
    self->events_.push_back({InputEvent::Type::cursor, 0, 0, 0, self->cursor_, {}});
  }
  static void scroll(GLFWwindow* w, double dx, double dy) {
    EditorWindow* self = owner(w);
    self->events_.push_back(
        {InputEvent::Type::scroll, 0, 0, 0, self->cursor_, {static_cast<float>(dx), static_cast<float>(dy)}});
  }
  static void key(GLFWwindow* w, int key, int, int action, int mods) {
    EditorWindow* self = owner(w);
    self->events_.push_back({InputEvent::Type::key, key, action, mods, self->cursor_, {}});
  }
  static void drop(GLFWwindow* w, int count, const char** paths) {
    for (int i = 0; i < count; ++i) owner(w)->drops_.emplace_back(paths[i]);
  }
  static void content_scale(GLFWwindow* w, float x, float y) {
    EditorWindow* self = owner(w);
    if (!self->fixed_scale_) self->pending_scale_ = std::max(x, y);
  }
};

EditorWindow::EditorWindow(int width, int height, const std::string& title, float ui_scale) {
  if (!glfwInit()) throw std::runtime_error("cannot open a window: " + glfw_error());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (!window_) {
    const std::string why = glfw_error();
    glfwTerminate();
    throw std::runtime_error("cannot create an OpenGL 3.3 core window: " + why);
  }
  glfwMakeContextCurrent(window_);
  glfwSwapInterval(1);
  if (gladLoadGL(glfwGetProcAddress) == 0) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw std::runtime_error("cannot load the OpenGL functions");
  }
  glfwSetWindowUserPointer(window_, this);
  cursor_ = cursor_of(window_);
  glfwSetMouseButtonCallback(window_, WindowCallbacks::button);
  glfwSetCursorPosCallback(window_, WindowCallbacks::cursor);
  glfwSetScrollCallback(window_, WindowCallbacks::scroll);
  glfwSetKeyCallback(window_, WindowCallbacks::key);
  glfwSetDropCallback(window_, WindowCallbacks::drop);
  glfwSetWindowContentScaleCallback(window_, WindowCallbacks::content_scale);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini in the user's folder
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");
  imgui_ready_ = true;

  fixed_scale_ = ui_scale > 0.0f;
  float x = 1.0f, y = 1.0f;
  glfwGetWindowContentScale(window_, &x, &y);
  apply_ui_scale(fixed_scale_ ? ui_scale : std::max(x, y), false);
}

EditorWindow::~EditorWindow() {
  if (imgui_ready_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void EditorWindow::apply_ui_scale(float scale, bool upload) {
  ui_scale_ = std::clamp(scale, 0.5f, 4.0f);
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  ImFont* font = nullptr;
  for (const char* path : kFonts) {
    if (!std::filesystem::exists(path)) continue;
    font = io.Fonts->AddFontFromFileTTF(path, std::round(15.0f * ui_scale_));
    if (font) break;
  }
  if (!font) {
    ImFontConfig config;
    config.SizePixels = std::round(13.0f * ui_scale_);
    io.Fonts->AddFontDefault(&config);
  }
  if (upload) {
    ImGui_ImplOpenGL3_DestroyFontsTexture();
    ImGui_ImplOpenGL3_CreateFontsTexture();
  }
  ImGuiStyle style;
  ImGui::StyleColorsDark(&style);
  style.WindowRounding = 4.0f;
  style.FrameRounding = 3.0f;
  style.GrabRounding = 3.0f;
  style.WindowBorderSize = 0.0f;
  style.Colors[ImGuiCol_WindowBg].w = 0.92f;
  style.ScaleAllSizes(ui_scale_);
  ImGui::GetStyle() = style;
}

bool EditorWindow::should_close() const { return glfwWindowShouldClose(window_) != 0; }

void EditorWindow::request_close() { glfwSetWindowShouldClose(window_, GLFW_TRUE); }

void EditorWindow::hide() { glfwHideWindow(window_); }

void EditorWindow::set_title(const std::string& title) { glfwSetWindowTitle(window_, title.c_str()); }

void EditorWindow::begin_frame(double timeout) {
  if (timeout > 0.0)
    glfwWaitEventsTimeout(timeout);
  else
    glfwPollEvents();
  if (pending_scale_ > 0.0f) {
    apply_ui_scale(pending_scale_, true);
    pending_scale_ = 0.0f;
  }
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void EditorWindow::render_ui() {
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void EditorWindow::present() { glfwSwapBuffers(window_); }

std::vector<InputEvent> EditorWindow::take_events() { return std::exchange(events_, {}); }

std::vector<std::string> EditorWindow::take_dropped_paths() { return std::exchange(drops_, {}); }

Viewport EditorWindow::viewport() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return Viewport{0, 0, w, h};
}

glm::vec2 EditorWindow::pixels_per_unit() const {
  int fw = 0, fh = 0, ww = 0, wh = 0;
  glfwGetFramebufferSize(window_, &fw, &fh);
  glfwGetWindowSize(window_, &ww, &wh);
  if (ww <= 0 || wh <= 0) return {1.0f, 1.0f};
  return {static_cast<float>(fw) / static_cast<float>(ww), static_cast<float>(fh) / static_cast<float>(wh)};
}

std::string EditorWindow::gl_description() const {
  const auto* version = reinterpret_cast<const char*>(glGetString(GL_VERSION));
  const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  return std::string(version ? version : "?") + ", " + (renderer ? renderer : "?");
}

void EditorWindow::wake() { glfwPostEmptyEvent(); }

}  // namespace amls::editor
