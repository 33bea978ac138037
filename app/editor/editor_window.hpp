#pragma once
// The editor's window: GLFW with an OpenGL 3.3 core context loaded by glad,
// and Dear ImGui (1.86) on top, scaled for the monitor's content scale (fonts
// and sizes). Input arrives as events - buttons, cursor, scroll, keys, each
// with its own position and modifiers - so that a press and release within one
// frame are never lost (ImGui 1.86 only keeps key states), and files dropped
// on the window arrive as paths. Main thread only, except wake().
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "render/render_options.hpp"

struct GLFWwindow;

namespace amls::editor {

struct WindowCallbacks;

struct InputEvent {
  enum class Type { button, cursor, scroll, key };
  Type type = Type::cursor;
  int code = 0;              // GLFW mouse button or key
  int action = 0;            // GLFW_PRESS, GLFW_RELEASE, GLFW_REPEAT
  int mods = 0;              // GLFW_MOD_* at the time
  glm::vec2 position{0.0f};  // the cursor in window units
  glm::vec2 scroll{0.0f};
};

class EditorWindow {
 public:
  // Throws std::runtime_error if there is no display or no OpenGL 3.3 core context.
  // `ui_scale` 0 takes the monitor's content scale.
  EditorWindow(int width, int height, const std::string& title, float ui_scale);
  ~EditorWindow();
  EditorWindow(const EditorWindow&) = delete;
  EditorWindow& operator=(const EditorWindow&) = delete;

  bool should_close() const;
  void request_close();
  void hide();
  void set_title(const std::string& title);
  // Waits up to `timeout` seconds for an event (0: only polls), then starts the ImGui frame.
  void begin_frame(double timeout);
  // Draws ImGui over the frame; present() shows it.
  void render_ui();
  void present();

  std::vector<InputEvent> take_events();
  std::vector<std::string> take_dropped_paths();

  Viewport viewport() const;          // the whole framebuffer, in pixels
  glm::vec2 pixels_per_unit() const;  // framebuffer pixels per window unit (high-DPI)
  float ui_scale() const { return ui_scale_; }
  std::string gl_description() const;

  // Wakes a begin_frame() that waits; callable from any thread.
  static void wake();

 private:
  friend struct WindowCallbacks;
  // Fonts and sizes for `scale`; `upload` replaces the font texture (after the first frame made it).
  void apply_ui_scale(float scale, bool upload);

  GLFWwindow* window_ = nullptr;
  float ui_scale_ = 1.0f;
  bool fixed_scale_ = false;
  float pending_scale_ = 0.0f;  // a content-scale change to apply before the next frame
  std::vector<InputEvent> events_;
  glm::vec2 cursor_{0.0f};  // where the last cursor event left the cursor (see WindowCallbacks)
  std::vector<std::string> drops_;
  bool imgui_ready_ = false;
};

}  // namespace amls::editor
