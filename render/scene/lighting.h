#pragma once
// The light rig and the key light's shadow frustum, without GL. Lights follow the camera so that
// every view is lit alike: the key light from above, a little in front of and to the left of the
// camera (shadows fall back and to the right, where they are seen), a weak fill from the right.
#include <Eigen/Geometry>

#include "render/scene/camera.h"

namespace stanceplan::render {

struct Lights {
  Eigen::Vector3d key_W;   // unit vector towards the key light
  Eigen::Vector3d fill_W;  // unit vector towards the fill light
};

Lights lights_for(const Camera& camera);

struct ShadowFrustum {
  Eigen::Matrix4d light_matrix;  // world -> the shadow map's clip space (orthographic)
  double depth_range = 1.0;      // metres covered by its depth
};

// The orthographic frustum of the key light that covers the subject (`focus`) and its shadow on
// the ground plane, tightly (the map's cost on llvmpipe grows with the subject's area in it, and
// its sharpness with the texel density), and in depth every caster (`casters`).
ShadowFrustum shadow_frustum(const Lights& lights, const Eigen::AlignedBox3d& focus,
                             const Eigen::AlignedBox3d& casters, double ground_z);

// Orthographic projection of a box given in view coordinates (looking down the view's -z).
Eigen::Matrix4d orthographic(const Eigen::AlignedBox3d& box_V);
// Extends `out` by the corners of `box` transformed by T (nothing for an empty box).
void extend_transformed(const Eigen::AlignedBox3d& box, const Eigen::Matrix4d& T,
                        Eigen::AlignedBox3d* out);

}  // namespace stanceplan::render
