#pragma once
// The few OpenGL calls the panel makes in the window's own context, through function pointers
// from glfwGetProcAddress. The process links gl* from libOSMesa for the renderer (render/gl/gl.h);
// calling those symbols here would reach whichever context Mesa's shared dispatch has current on
// this thread, which only works by accident of both being Mesa (docs/DEPENDENCIES.md section 5). A
// table per context is the portable way; ImGui's OpenGL3 backend loads its own the same way.
#include <GL/gl.h>

namespace stanceplan::gui {

struct WindowGl {
  void(GLAPIENTRY* GenTextures)(GLsizei, GLuint*) = nullptr;
  void(GLAPIENTRY* DeleteTextures)(GLsizei, const GLuint*) = nullptr;
  void(GLAPIENTRY* BindTexture)(GLenum, GLuint) = nullptr;
  void(GLAPIENTRY* TexParameteri)(GLenum, GLenum, GLint) = nullptr;
  void(GLAPIENTRY* TexImage2D)(GLenum, GLint, GLint, GLsizei, GLsizei, GLint, GLenum, GLenum,
                               const void*) = nullptr;
  void(GLAPIENTRY* TexSubImage2D)(GLenum, GLint, GLint, GLint, GLsizei, GLsizei, GLenum, GLenum,
                                  const void*) = nullptr;
  void(GLAPIENTRY* PixelStorei)(GLenum, GLint) = nullptr;
  void(GLAPIENTRY* Viewport)(GLint, GLint, GLsizei, GLsizei) = nullptr;
  void(GLAPIENTRY* ClearColor)(GLfloat, GLfloat, GLfloat, GLfloat) = nullptr;
  void(GLAPIENTRY* Clear)(GLbitfield) = nullptr;
  void(GLAPIENTRY* ReadBuffer)(GLenum) = nullptr;
  void(GLAPIENTRY* ReadPixels)(GLint, GLint, GLsizei, GLsizei, GLenum, GLenum, void*) = nullptr;
  void(GLAPIENTRY* Finish)() = nullptr;
  const GLubyte*(GLAPIENTRY* GetString)(GLenum) = nullptr;

  // Loads every entry point for the window context current on this thread; throws
  // std::runtime_error naming the first one missing.
  static WindowGl load();
};

}  // namespace stanceplan::gui
