#include "render/scene/draw_list.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace stanceplan::render {

Eigen::AlignedBox3d DrawItem::world_bounds() const {
  Eigen::AlignedBox3d box;
  const Eigen::AlignedBox3f local = mesh->bounds();
  if (local.isEmpty()) return box;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3f c = local.corner(static_cast<Eigen::AlignedBox3f::CornerType>(i));
    box.extend((T_WM * c.homogeneous()).head<3>().cast<double>());
  }
  return box;
}

Eigen::AlignedBox3d DrawList::bounds(bool all_items) const {
  Eigen::AlignedBox3d box;
  for (const DrawItem& item : items)
    if (all_items || item.frames_view) box.extend(item.world_bounds());
  return box;
}

namespace {

// Slab test: does the segment a-b cross the box?
bool segment_hits_box(const Eigen::Vector3f& a, const Eigen::Vector3f& b,
                      const Eigen::AlignedBox3f& box) {
  float t0 = 0.0f, t1 = 1.0f;
  const Eigen::Vector3f d = b - a;
  for (int k = 0; k < 3; ++k) {
    if (std::abs(d[k]) < 1e-12f) {
      if (a[k] < box.min()[k] || a[k] > box.max()[k]) return false;
      continue;
    }
    float ta = (box.min()[k] - a[k]) / d[k], tb = (box.max()[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace

std::vector<bool> occluding_environment(const DrawList& list, const Eigen::Vector3d& eye,
                                        const Eigen::AlignedBox3d& focus) {
  std::vector<Eigen::Vector3d> samples = {focus.center()};
  for (int i = 0; i < 8; ++i)
    samples.push_back(
        focus.center() +
        0.8 * (focus.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i)) - focus.center()));
  std::vector<bool> out(list.items.size(), false);
  for (size_t i = 0; i < list.items.size(); ++i) {
    const DrawItem& item = list.items[i];
    if (!item.environment || item.layer != Layer::Solid) continue;
    // Test in the mesh's own frame, where its bounds are an axis-aligned box.
    const Eigen::Matrix4f inverse = item.T_WM.inverse();
    const Eigen::AlignedBox3f local = item.mesh->bounds();
    const Eigen::Vector3f eye_M = (inverse * eye.cast<float>().homogeneous()).head<3>();
    // A third of the sight lines blocked: a wall in front, not a chair seat under the thighs.
    int blocked = 0;
    for (const Eigen::Vector3d& p : samples)
      blocked += segment_hits_box(eye_M, (inverse * p.cast<float>().homogeneous()).head<3>(), local)
                     ? 1
                     : 0;
    out[i] = 3 * blocked >= static_cast<int>(samples.size());
  }
  return out;
}

Eigen::Matrix4f scaled_transform(const Eigen::Isometry3d& T, const Eigen::Vector3d& scale) {
  Eigen::Matrix4d m = T.matrix();
  m.topLeftCorner<3, 3>() = T.linear() * scale.asDiagonal();
  return m.cast<float>();
}

Eigen::Matrix3d rotation_z_to(const Eigen::Vector3d& direction) {
  const Eigen::Vector3d z = direction.normalized();
  // Any axis not parallel to z completes the frame.
  const Eigen::Vector3d helper =
      std::abs(z.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  const Eigen::Vector3d x = helper.cross(z).normalized();
  Eigen::Matrix3d R;
  R.col(0) = x;
  R.col(1) = z.cross(x);
  R.col(2) = z;
  return R;
}

}  // namespace stanceplan::render
