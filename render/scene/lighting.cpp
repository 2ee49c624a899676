#include "render/scene/lighting.h"

#include <algorithm>
#include <cmath>

namespace stanceplan::render {

Lights lights_for(const Camera& camera) {
  const Eigen::Vector3d f = (camera.target - camera.eye).normalized();
  const Eigen::Vector3d right = f.cross(camera.up).normalized();
  Eigen::Vector3d back(-f.x(), -f.y(), 0.0);
  back = back.norm() > 1e-6 ? back.normalized() : Eigen::Vector3d::Zero();
  return {(Eigen::Vector3d::UnitZ() + 0.55 * back - 0.45 * right).normalized(),
          (0.6 * back + 0.8 * right + 0.3 * Eigen::Vector3d::UnitZ()).normalized()};
}

Eigen::Matrix4d orthographic(const Eigen::AlignedBox3d& box_V) {
  // The view looks down its -z axis: the near plane is at -max.z, the far plane at -min.z.
  const Eigen::Vector3d lo = box_V.min(), hi = box_V.max();
  const double near = -hi.z(), far = -lo.z();
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m(0, 0) = 2.0 / (hi.x() - lo.x());
  m(1, 1) = 2.0 / (hi.y() - lo.y());
  m(2, 2) = -2.0 / (far - near);
  m(0, 3) = -(hi.x() + lo.x()) / (hi.x() - lo.x());
  m(1, 3) = -(hi.y() + lo.y()) / (hi.y() - lo.y());
  m(2, 3) = -(far + near) / (far - near);
  return m;
}

void extend_transformed(const Eigen::AlignedBox3d& box, const Eigen::Matrix4d& T,
                        Eigen::AlignedBox3d* out) {
  if (box.isEmpty()) return;
  for (int i = 0; i < 8; ++i)
    out->extend(
        (T * box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)).homogeneous()).head<3>());
}

ShadowFrustum shadow_frustum(const Lights& lights, const Eigen::AlignedBox3d& focus,
                             const Eigen::AlignedBox3d& casters, double ground_z) {
  // The subject and where its shadow falls: its corners projected along the light to the ground.
  Eigen::AlignedBox3d region = focus;
  region.min().z() = std::min(region.min().z(), ground_z);
  const double key_z = std::max(lights.key_W.z(), 0.2);
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d c = focus.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i));
    region.extend(c - lights.key_W * std::max(c.z() - ground_z, 0.0) / key_z);
  }
  region.min() -= Eigen::Vector3d::Constant(0.05);
  region.max() += Eigen::Vector3d::Constant(0.05);

  Camera light;
  light.target = region.center();
  light.eye = region.center() + (region.max() - region.min()).norm() * lights.key_W;
  light.up =
      std::abs(lights.key_W.z()) > 0.95 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitZ();
  const Eigen::Matrix4d light_view = light.view_matrix();
  Eigen::AlignedBox3d box_V, casters_V;
  extend_transformed(region, light_view, &box_V);
  extend_transformed(casters, light_view, &casters_V);
  if (!casters_V.isEmpty()) {
    box_V.min().z() = std::min(box_V.min().z(), casters_V.min().z());
    box_V.max().z() = std::max(box_V.max().z(), casters_V.max().z());
  }
  box_V.min().z() -= 0.01;
  box_V.max().z() += 0.01;
  return {orthographic(box_V) * light_view, box_V.max().z() - box_V.min().z()};
}

}  // namespace stanceplan::render
