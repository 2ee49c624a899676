#pragma once
// The GLFW window with its OpenGL 3.3 core context and the Dear ImGui context drawn into it
// through the GLFW and OpenGL3 backends compiled into Debian's libimgui.a (docs/DEPENDENCIES.md
// section 6). Thin: frames begin and end here, everything shown is drawn by the panel sections.
// Use from one thread (the one that made it): the window's context stays current on it.
#include <string>

#include "app/gui/window_gl.h"
#include "render/image/image.h"

struct GLFWwindow;

namespace stanceplan::gui {

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
  // Starts an ImGui frame.
  void begin_frame();
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
