#pragma once
// GLSL 3.30 core sources of the renderer's programs. Private to render/.
//
// Surfaces are shaded by variants of one fragment shader, selected with preprocessor flags, so
// that each pixel runs only what it needs: llvmpipe shades on the CPU and executes both sides of
// a branch, so a uniform `if` would cost as much as the code it skips.
#include <string>

namespace stanceplan::render::shaders {

enum SurfaceFlags : unsigned {
  kLit = 1u << 0,        // lighting (otherwise the flat colour)
  kShadows = 1u << 1,    // key-light shadow map
  kSpecular = 1u << 2,   // highlights, fill and rim light (robots, overlays)
  kFade = 1u << 3,       // far geometry fades into the background (environment)
  kGrid = 1u << 4,       // grid lines on upward surfaces lying on the ground
  kFloorQuad = 1u << 5,  // the ground quad: fades by transparency, may be lines only
};

std::string mesh_vertex();  // world position, normal, colour, light-space position
std::string surface_fragment(unsigned flags);
std::string depth_vertex();  // shadow map pass
std::string depth_fragment();
std::string background_vertex();  // full-screen triangle from gl_VertexID
std::string background_fragment();

}  // namespace stanceplan::render::shaders
