#include "app/gui/gui_window.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <stdexcept>

#include "app/gui/ui_style.h"

namespace stanceplan::gui {
namespace {

std::string glfw_error() {
  const char* description = nullptr;
  const int code = glfwGetError(&description);
  return description != nullptr
             ? std::string(description) + " (GLFW error " + std::to_string(code) + ")"
             : "unknown GLFW error";
}

// Counts input, so that an idle panel need not redraw. Installed before ImGui's backend, which
// calls them from its own callbacks (the cursor, size and refresh ones it does not install).
GuiWindow* owner(GLFWwindow* w) {
  return static_cast<GuiWindow*>(glfwGetWindowUserPointer(w));
}
void on_input(GLFWwindow* w) {
  owner(w)->note_input();
}

void install_input_counters(GLFWwindow* window) {
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int, int, int) { on_input(w); });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double) { on_input(w); });
  glfwSetKeyCallback(window, [](GLFWwindow* w, int, int, int, int) { on_input(w); });
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int) { on_input(w); });
  glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { on_input(w); });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { on_input(w); });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) { on_input(w); });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { on_input(w); });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { on_input(w); });
}

}  // namespace

GuiWindow::GuiWindow(int width, int height, const std::string& title) {
  if (glfwInit() != GLFW_TRUE) throw std::runtime_error("cannot open a window: " + glfw_error());
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
  if (window_ == nullptr) {
    const std::string why = glfw_error();
    glfwTerminate();
    throw std::runtime_error("cannot open a window: " + why);
  }
  glfwMakeContextCurrent(window_);
  glfwSetWindowUserPointer(window_, this);
  install_input_counters(window_);
  glfwSwapInterval(1);
  try {
    gl_ = WindowGl::load();
  } catch (...) {
    glfwDestroyWindow(window_);
    glfwTerminate();
    throw;
  }
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename =
      nullptr;  // the layout is fixed: no imgui.ini beside the user's files
  apply_ui_style();
  imgui_glfw_ = ImGui_ImplGlfw_InitForOpenGL(window_, true);
  imgui_gl3_ = imgui_glfw_ && ImGui_ImplOpenGL3_Init("#version 330 core");
  if (!imgui_gl3_) {
    shutdown();
    throw std::runtime_error("cannot start Dear ImGui's OpenGL 3 backend in the window");
  }
}

GuiWindow::~GuiWindow() {
  shutdown();
}

void GuiWindow::shutdown() {
  if (window_ == nullptr) return;
  if (imgui_gl3_) ImGui_ImplOpenGL3_Shutdown();
  if (imgui_glfw_) ImGui_ImplGlfw_Shutdown();
  imgui_gl3_ = imgui_glfw_ = false;
  if (ImGui::GetCurrentContext() != nullptr) ImGui::DestroyContext();
  glfwDestroyWindow(window_);
  window_ = nullptr;
  glfwTerminate();
}

bool GuiWindow::should_close() const {
  return glfwWindowShouldClose(window_) == GLFW_TRUE;
}

void GuiWindow::request_close() {
  glfwSetWindowShouldClose(window_, GLFW_TRUE);
}

void GuiWindow::wait_events(double timeout_s) {
  if (timeout_s > 0.0)
    glfwWaitEventsTimeout(timeout_s);
  else
    glfwPollEvents();
}

void GuiWindow::begin_frame(const std::optional<ScriptedPointer>& pointer) {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();  // reads the real mouse into ImGui's IO (ImGui 1.86)
  if (pointer) {              // ... which the scripted pointer then overrides, before NewFrame
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(pointer->x, pointer->y);
    io.MouseDown[ImGuiMouseButton_Left] = pointer->left;
    io.MouseDown[ImGuiMouseButton_Right] = pointer->right;
    io.MouseWheel = pointer->wheel;
  }
  ImGui::NewFrame();
}

void GuiWindow::end_frame(render::Color clear) {
  ImGui::Render();
  gl_.Viewport(0, 0, framebuffer_width(), framebuffer_height());
  gl_.ClearColor(clear.r, clear.g, clear.b, 1.0f);
  gl_.Clear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

render::Image GuiWindow::read_back_buffer() const {
  const int w = framebuffer_width(), h = framebuffer_height();
  render::Image image(w, h);
  gl_.Finish();
  gl_.ReadBuffer(GL_BACK);
  gl_.PixelStorei(GL_PACK_ALIGNMENT, 1);
  std::vector<std::uint8_t> rows(static_cast<size_t>(w) * h * 4);
  gl_.ReadPixels(0, 0, w, h, GL_RGBA, GL_UNSIGNED_BYTE, rows.data());
  // OpenGL's row 0 is the bottom of the window.
  const size_t stride = static_cast<size_t>(w) * 4;
  for (int y = 0; y < h; ++y)
    std::copy_n(rows.data() + (h - 1 - y) * stride, stride, image.pixel(0, y));
  for (size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = 255;
  return image;
}

void GuiWindow::present() {
  glfwSwapBuffers(window_);
}

int GuiWindow::framebuffer_width() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return w;
}

int GuiWindow::framebuffer_height() const {
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  return h;
}

std::string GuiWindow::gl_renderer() const {
  const auto* name = reinterpret_cast<const char*>(gl_.GetString(GL_RENDERER));
  return name != nullptr ? name : "";
}

}  // namespace stanceplan::gui
