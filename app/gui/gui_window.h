#pragma once
// The GLFW window with its OpenGL 3.3 core context and the Dear ImGui context drawn into it
// through the GLFW and OpenGL3 backends compiled into Debian's libimgui.a (docs/DEPENDENCIES.md
// section 6). Thin: frames begin and end here, everything shown is drawn by the panel sections.
// Use from one thread (the one that made it): the window's context stays current on it.
#include <optional>
#include <string>

#include "app/gui/window_gl.h"
#include "render/image/image.h"

struct GLFWwindow;

namespace stanceplan::gui {

// A pointer state that replaces the real mouse's for the frames it is set (scripted panels):
// ImGui then sees it exactly as it would see a user's (hover, clicks, drags, the wheel).
struct ScriptedPointer {
  float x = 0.0f, y = 0.0f;  // window coordinates (ImGui's units)
  bool left = false, right = false;
  float wheel = 0.0f;  // clicks this frame (positive: away from the user)
};

class GuiWindow {
 public:
  // Throws std::runtime_error with GLFW's description when there is no display or no context.
  GuiWindow(int width, int height, const std::string& title);
  ~GuiWindow();
  GuiWindow(const GuiWindow&) = delete;
  GuiWindow& operator=(const GuiWindow&) = delete;

  bool should_close() const;
  void request_close();
  // Waits for input at most `timeout_s` (0: only polls).
  void wait_events(double timeout_s);
  // Starts an ImGui frame; with a scripted pointer, ImGui sees it instead of the mouse.
  void begin_frame(const std::optional<ScriptedPointer>& pointer = std::nullopt);
  // Clears the back buffer to `clear` and draws the ImGui frame into it.
  void end_frame(render::Color clear);
  // The back buffer as drawn by end_frame (read before present()), rows top-down, opaque.
  render::Image read_back_buffer() const;
  void present();

  // Input events (mouse, keys, focus, resize) since the window opened: unchanged means the user
  // did nothing.
  long input_events() const { return input_events_; }
  void note_input() { ++input_events_; }

  int framebuffer_width() const;
  int framebuffer_height() const;
  const WindowGl& gl() const { return gl_; }
  std::string gl_renderer() const;

 private:
  void shutdown();

  GLFWwindow* window_ = nullptr;
  WindowGl gl_;
  bool imgui_glfw_ = false;
  bool imgui_gl3_ = false;
  long input_events_ = 0;
};

}  // namespace stanceplan::gui
