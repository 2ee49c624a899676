#include "app/gui/view_texture.h"

namespace stanceplan::gui {

ViewTexture::~ViewTexture() {
  if (texture_ != 0) gl_.DeleteTextures(1, &texture_);
}

void ViewTexture::upload(const render::Image& image) {
  if (image.empty()) return;
  if (texture_ == 0) {
    gl_.GenTextures(1, &texture_);
    gl_.BindTexture(GL_TEXTURE_2D, texture_);
    // Shown at its own size; when the view is resized before a new image arrives, a scaled one.
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    gl_.TexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  }
  gl_.BindTexture(GL_TEXTURE_2D, texture_);
  gl_.PixelStorei(GL_UNPACK_ALIGNMENT, 1);
  // Row 0 of the image is its top: ImGui draws the texture with v = 0 at the top, so no flip.
  if (image.width == width_ && image.height == height_) {
    gl_.TexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE,
                      image.rgba.data());
  } else {
    width_ = image.width;
    height_ = image.height;
    gl_.TexImage2D(GL_TEXTURE_2D, 0, GL_RGBA8, width_, height_, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                   image.rgba.data());
  }
  gl_.BindTexture(GL_TEXTURE_2D, 0);
}

}  // namespace stanceplan::gui
