#include "planner/search/failure_memo.h"

#include <algorithm>
#include <cmath>

namespace stanceplan {
namespace {

// Every joint of every entity, floating bases left out (where the robot stands is not its
// posture).
Eigen::VectorXd joint_angles(const System& system, const Eigen::VectorXd& q) {
  std::vector<double> out;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    for (int k = entity.first_dof(); k < entity.nq(); ++k) out.push_back(q[system.offset(e) + k]);
  }
  return Eigen::Map<const Eigen::VectorXd>(out.data(), static_cast<long>(out.size()));
}

Eigen::Isometry3d surface_pose_W(const Scene& scene, const std::vector<ModelData>& data,
                                 SurfaceRef r) {
  const Surface& s = scene.surfaces.get(r);
  return data[r.entity].T_WL[s.link] * s.T_LS;
}

// Distance from a point of a convex polygon's plane to the polygon (0 inside); the polygon is
// counter-clockwise about +z.
double outside_polygon(const std::vector<Eigen::Vector2d>& polygon, const Eigen::Vector2d& p) {
  double outside = 0.0;
  const size_t n = polygon.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d a = polygon[i], edge = polygon[(i + 1) % n] - a;
    const Eigen::Vector2d outward(edge.y(), -edge.x());
    outside = std::max(outside, outward.normalized().dot(p - a));
  }
  return outside;
}

bool same_change(const Candidate& a, const Candidate& b) {
  return a.add == b.add && a.contact.same_surfaces(b.contact);
}

}  // namespace

FailureMemo::Relation FailureMemo::relation(const Scene& scene, const std::vector<ModelData>& data,
                                            const Contact& c) {
  const Eigen::Isometry3d T_S2S1 =
      surface_pose_W(scene, data, c.s2).inverse() * surface_pose_W(scene, data, c.s1);
  Relation r;
  r.height = T_S2S1.translation().z();
  r.outside = outside_polygon(scene.surfaces.get(c.s2).vertices_S, T_S2S1.translation().head<2>());
  // A point surface has no normal: its tilt is 0.
  r.tilt = scene.surfaces.get(c.s1).is_point()
               ? 0.0
               : std::acos(std::clamp(-T_S2S1.linear()(2, 2), -1.0, 1.0));
  return r;
}

void FailureMemo::record(const Scene& scene, const std::vector<ModelData>& data,
                         const Eigen::VectorXd& q, const Stance& stance,
                         const Candidate& candidate) {
  entries_.push_back(
      {candidate, stance, joint_angles(scene.system, q), relation(scene, data, candidate.contact)});
}

bool FailureMemo::seen(const Scene& scene, const std::vector<ModelData>& data,
                       const Eigen::VectorXd& q, const Stance& stance,
                       const Candidate& candidate) const {
  const Eigen::VectorXd joints = joint_angles(scene.system, q);
  const Relation now = relation(scene, data, candidate.contact);
  for (const Entry& e : entries_) {
    if (!same_change(e.candidate, candidate) || !(e.stance == stance)) continue;
    if (joints.size() > 0 && (e.joints - joints).cwiseAbs().maxCoeff() > kJointRadius) continue;
    const Relation& then = e.relation;
    if (std::abs(then.height - now.height) > kPlaceRadius ||
        std::abs(then.outside - now.outside) > kPlaceRadius ||
        std::abs(then.tilt - now.tilt) > kTiltRadius)
      continue;
    return true;
  }
  return false;
}

}  // namespace stanceplan
