#include "render/gl/render_targets.h"

#include <cstring>
#include <stdexcept>

#include "render/gl/gl.h"
#include "render/gl/gl_context.h"

namespace stanceplan::render {
namespace {

void expect_complete(const char* what) {
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw std::runtime_error(std::string("Renderer: the ") + what + " framebuffer is incomplete");
}

unsigned renderbuffer(int samples, GLenum format, int width, int height) {
  unsigned id = 0;
  glGenRenderbuffers(1, &id);
  glBindRenderbuffer(GL_RENDERBUFFER, id);
  if (samples > 1)
    glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, width, height);
  else
    glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  return id;
}

}  // namespace

RenderTargets::RenderTargets(int width, int height, int samples, int shadow_size)
    : width_(width), height_(height), multisampled_(samples > 1), shadow_size_(shadow_size) {
  glGenFramebuffers(1, &scene_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
  scene_color_ = renderbuffer(samples, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, scene_color_);
  // Stencil marks the subject's pixels, so that see-through occluders can skip them.
  scene_depth_ = renderbuffer(samples, GL_DEPTH24_STENCIL8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                            scene_depth_);
  expect_complete("scene");

  if (multisampled_) {
    glGenFramebuffers(1, &resolve_fbo_);
    glBindFramebuffer(GL_FRAMEBUFFER, resolve_fbo_);
    resolve_color_ = renderbuffer(1, GL_RGBA8, width, height);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                              resolve_color_);
    expect_complete("resolve");
  }

  // Depth texture compared in hardware (sampler2DShadow), bilinear: filtered shadow edges.
  glGenTextures(1, &shadow_texture_);
  glBindTexture(GL_TEXTURE_2D, shadow_texture_);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_DEPTH_COMPONENT24, shadow_size, shadow_size, 0,
               GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, nullptr);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
  glGenFramebuffers(1, &shadow_fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
  glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, shadow_texture_, 0);
  glDrawBuffer(GL_NONE);
  glReadBuffer(GL_NONE);
  expect_complete("shadow");
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("RenderTargets");
}

RenderTargets::~RenderTargets() {
  glDeleteFramebuffers(1, &scene_fbo_);
  glDeleteRenderbuffers(1, &scene_color_);
  glDeleteRenderbuffers(1, &scene_depth_);
  glDeleteFramebuffers(1, &resolve_fbo_);
  glDeleteRenderbuffers(1, &resolve_color_);
  glDeleteFramebuffers(1, &shadow_fbo_);
  glDeleteTextures(1, &shadow_texture_);
}

void RenderTargets::bind_scene() const {
  glBindFramebuffer(GL_FRAMEBUFFER, scene_fbo_);
  glViewport(0, 0, width_, height_);
}

void RenderTargets::bind_shadow() const {
  glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_);
  glViewport(0, 0, shadow_size_, shadow_size_);
}

Image RenderTargets::read() {
  if (multisampled_) {
    glBindFramebuffer(GL_READ_FRAMEBUFFER, scene_fbo_);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, resolve_fbo_);
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  }
  glBindFramebuffer(GL_READ_FRAMEBUFFER, multisampled_ ? resolve_fbo_ : scene_fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  readback_.resize(static_cast<size_t>(width_) * height_ * 4);
  glReadPixels(0, 0, width_, height_, GL_RGBA, GL_UNSIGNED_BYTE, readback_.data());
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  check_gl("Renderer::render");
  // GL rows go bottom-up; images are top-down.
  Image image;
  image.width = width_;
  image.height = height_;
  image.rgba.resize(readback_.size());
  const size_t row = static_cast<size_t>(width_) * 4;
  for (int y = 0; y < height_; ++y)
    std::memcpy(&image.rgba[y * row], &readback_[(height_ - 1 - y) * row], row);
  return image;
}

}  // namespace stanceplan::render
