#pragma once
// An RGBA image shown in the window: one OpenGL texture of the window's context, replaced in
// place when a new image of the same size arrives. Use on the window's thread only.
#include <cstdint>

#include "app/gui/window_gl.h"
#include "render/image/image.h"

namespace stanceplan::gui {

class ViewTexture {
 public:
  explicit ViewTexture(const WindowGl& gl) : gl_(gl) {}
  ~ViewTexture();
  ViewTexture(const ViewTexture&) = delete;
  ViewTexture& operator=(const ViewTexture&) = delete;

  void upload(const render::Image& image);  // rows top-down, as the renderer returns them
  bool empty() const { return texture_ == 0; }
  int width() const { return width_; }
  int height() const { return height_; }
  // For ImGui::Image (the OpenGL3 backend's ImTextureID is the texture name).
  void* id() const { return reinterpret_cast<void*>(static_cast<std::uintptr_t>(texture_)); }

 private:
  const WindowGl& gl_;
  GLuint texture_ = 0;
  int width_ = 0;
  int height_ = 0;
};

}  // namespace stanceplan::gui
