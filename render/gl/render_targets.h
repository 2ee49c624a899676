#pragma once
// The framebuffers one Renderer draws into: a (multisampled) colour + depth/stencil target of the
// image size, a single-sample resolve target when multisampled, and the key light's shadow map.
// Needs its GL context current. Private to render/.
#include <cstdint>
#include <vector>

#include "render/image/image.h"

namespace stanceplan::render {

class RenderTargets {
 public:
  // samples <= 1: no multisampling. Throws std::runtime_error when a framebuffer is incomplete.
  RenderTargets(int width, int height, int samples, int shadow_size);
  ~RenderTargets();
  RenderTargets(const RenderTargets&) = delete;
  RenderTargets& operator=(const RenderTargets&) = delete;

  void bind_scene() const;   // binds the scene target and sets the viewport
  void bind_shadow() const;  // binds the shadow map as the depth target and sets the viewport
  unsigned shadow_texture() const { return shadow_texture_; }
  int shadow_size() const { return shadow_size_; }
  // Resolves the samples (when multisampled) and reads the image back, rows flipped to top-down.
  Image read();

 private:
  int width_;
  int height_;
  bool multisampled_;
  int shadow_size_;
  unsigned scene_fbo_ = 0, scene_color_ = 0, scene_depth_ = 0;
  unsigned resolve_fbo_ = 0, resolve_color_ = 0;
  unsigned shadow_fbo_ = 0, shadow_texture_ = 0;
  std::vector<std::uint8_t> readback_;
};

}  // namespace stanceplan::render
