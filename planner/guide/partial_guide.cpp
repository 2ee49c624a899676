#include "planner/guide/partial_guide.h"

#include <Eigen/Geometry>
#include <algorithm>

#include "planner/guide/goal_posture.h"

namespace stanceplan {
namespace {

Eigen::Quaterniond orientation(const Eigen::VectorXd& q, int o) {
  const Eigen::Vector4d w = q.segment<4>(o + Entity::kBaseQuaternion);
  return Eigen::Quaterniond(w[0], w[1], w[2], w[3]).normalized();
}

bool stated(const Problem& problem, int e) {
  const int o = problem.scene.system.offset(e);
  for (const Eigen::VectorXd& mask : problem.milestone_masks)
    if (mask.segment<Entity::kFloatingBaseSize>(o).any()) return true;
  return false;
}

// Root e's pose at `share` of its travel along the path (position metres plus half a metre per
// radian, as GuideSpace::travel), written into q.
void pose_along(const std::vector<Eigen::VectorXd>& path, int o, double share, Eigen::VectorXd& q) {
  std::vector<double> at{0.0};
  for (size_t k = 1; k < path.size(); ++k)
    at.push_back(at.back() + (path[k].segment<3>(o) - path[k - 1].segment<3>(o)).norm() +
                 0.5 * orientation(path[k], o).angularDistance(orientation(path[k - 1], o)));
  const double d = share * at.back();
  size_t k = 1;
  while (k + 1 < path.size() && at[k] < d) ++k;
  const double length = at[k] - at[k - 1];
  const double t = length > 0.0 ? std::clamp((d - at[k - 1]) / length, 0.0, 1.0) : 1.0;
  q.segment<3>(o) = (1.0 - t) * path[k - 1].segment<3>(o) + t * path[k].segment<3>(o);
  const Eigen::Quaterniond r = orientation(path[k - 1], o).slerp(t, orientation(path[k], o));
  q.segment<4>(o + Entity::kBaseQuaternion) << r.w(), r.x(), r.y(), r.z();
}

}  // namespace

std::vector<int> unstated_moving_roots(const Problem& problem) {
  std::vector<int> roots;
  if (problem.milestones.empty()) return roots;
  const System& system = problem.scene.system;
  const Eigen::VectorXd carried = carried_configuration(problem);
  const Eigen::VectorXd& q0 = problem.initial_configuration;
  for (int e = 0; e < system.num_entities(); ++e) {
    if (!system.entity(e).floating() || stated(problem, e)) continue;
    const int o = system.offset(e);
    const bool moves = (carried.segment<3>(o) - q0.segment<3>(o)).norm() > kMoves ||
                       orientation(carried, o).angularDistance(orientation(q0, o)) > kTurns;
    if (moves) roots.push_back(e);
  }
  return roots;
}

void complete_milestones(Problem& problem, const ComputedGuide& guide,
                         const std::vector<int>& roots) {
  const System& system = problem.scene.system;
  const size_t n = problem.milestones.size();
  for (int e : roots) {
    const int o = system.offset(e);
    // A robot's heading follows its feet (guide_milestones.h): positions only; an object's turn
    // is part of its task.
    const bool turns =
        system.entity(e).kind == EntityKind::Object &&
        orientation(guide.q_goal, o)
                .angularDistance(orientation(problem.initial_configuration, o)) > 0.1;
    for (size_t i = 0; i < n; ++i) {
      const Eigen::Vector4d kept = problem.milestones[i].segment<4>(o + Entity::kBaseQuaternion);
      pose_along(guide.path, o, double(i + 1) / double(n), problem.milestones[i]);
      if (!turns) problem.milestones[i].segment<4>(o + Entity::kBaseQuaternion) = kept;
      problem.milestone_masks[i].segment<3>(o).setOnes();
      if (turns) problem.milestone_masks[i].segment<4>(o + Entity::kBaseQuaternion).setOnes();
    }
  }
}

}  // namespace stanceplan
