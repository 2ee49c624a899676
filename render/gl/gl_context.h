#pragma once
// An OSMesa OpenGL context (core profile 3.3; Mesa gives 4.5 core on llvmpipe). Needs no display
// and no X server. OpenGL contexts are bound to a thread: make_current() binds this context to
// the calling thread, and every GL call must then come from that thread.
#include <memory>
#include <string>

namespace stanceplan::render {

class GlContext {
 public:
  // Throws std::runtime_error when OSMesa cannot create a core-profile context.
  GlContext();
  ~GlContext();
  GlContext(const GlContext&) = delete;
  GlContext& operator=(const GlContext&) = delete;

  // Binds the context to the calling thread (a cheap no-op if it already is).
  void make_current();
  std::string renderer_name() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Throws std::runtime_error naming `where` and the GL error when glGetError reports one.
void check_gl(const char* where);

}  // namespace stanceplan::render
