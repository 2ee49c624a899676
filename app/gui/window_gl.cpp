#include "app/gui/window_gl.h"

#include <GLFW/glfw3.h>

#include <stdexcept>
#include <string>

namespace stanceplan::gui {
namespace {

template <typename F>
void load_one(F*& f, const char* name) {
  f = reinterpret_cast<F*>(glfwGetProcAddress(name));
  if (f == nullptr)
    throw std::runtime_error(std::string("OpenGL: the window context has no ") + name);
}

}  // namespace

WindowGl WindowGl::load() {
  WindowGl gl;
  load_one(gl.GenTextures, "glGenTextures");
  load_one(gl.DeleteTextures, "glDeleteTextures");
  load_one(gl.BindTexture, "glBindTexture");
  load_one(gl.TexParameteri, "glTexParameteri");
  load_one(gl.TexImage2D, "glTexImage2D");
  load_one(gl.TexSubImage2D, "glTexSubImage2D");
  load_one(gl.PixelStorei, "glPixelStorei");
  load_one(gl.Viewport, "glViewport");
  load_one(gl.ClearColor, "glClearColor");
  load_one(gl.Clear, "glClear");
  load_one(gl.ReadBuffer, "glReadBuffer");
  load_one(gl.ReadPixels, "glReadPixels");
  load_one(gl.Finish, "glFinish");
  load_one(gl.GetString, "glGetString");
  return gl;
}

}  // namespace stanceplan::gui
