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

bool states_no_joints(const Problem& problem) {
  const System& system = problem.scene.system;
  if (problem.milestones.empty()) return false;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    if (entity.kind != EntityKind::FloatingRobot || entity.model->num_dofs() == 0) continue;
    const int o = system.offset(e) + entity.first_dof();
    for (const Eigen::VectorXd& mask : problem.milestone_masks)
      if (mask.segment(o, entity.model->num_dofs()).any()) return false;
  }
  return true;
}

namespace {

// The entries of q that computed milestone k states: its roots' positions, headings and joints.
Eigen::VectorXd stated_entries(const System& system, const GuideMilestone& m) {
  Eigen::VectorXd mask = Eigen::VectorXd::Zero(system.nq());
  for (const GuideMilestone::Root& root : m.roots) {
    const int o = system.offset(root.entity);
    const Entity& entity = system.entity(root.entity);
    mask.segment<3>(o + Entity::kBasePosition).setOnes();
    if (root.rpy) mask.segment<4>(o + Entity::kBaseQuaternion).setOnes();
    if (root.joints) mask.segment(o + entity.first_dof(), entity.model->num_dofs()).setOnes();
  }
  return mask;
}

// Whether the goal stance keeps a contact of the initial one and adds one: what a posture change
// needs (posture_stages.h); otherwise no guide is computed only to find none (a goal 3 m up took
// 2 s of path planning).
bool keeps_and_adds(const Problem& problem) {
  bool keeps = false, adds = false;
  for (const StanceContact& g : problem.goal_stance)
    (problem.in_initial_stance(g.contact) ? keeps : adds) = true;
  return keeps && adds;
}

}  // namespace

void complete_posture_change(Problem& problem, const ComputedGuide& guide) {
  const System& system = problem.scene.system;
  const int first = guide.approach_milestones - 1;    // the approach's last milestone
  const int last = int(guide.milestones.size()) - 1;  // the last stage
  if (guide.stages <= 0 || first < 0 || problem.milestones.empty()) return;
  // The last written milestone: what it leaves out, from the last stage.
  const Eigen::VectorXd stage_mask = stated_entries(system, guide.milestones[size_t(last)]);
  Eigen::VectorXd& q_last = problem.milestones.back();
  Eigen::VectorXd& mask_last = problem.milestone_masks.back();
  for (Eigen::Index i = 0; i < q_last.size(); ++i)
    if (stage_mask[i] > 0.0 && !(mask_last[i] > 0.0)) {
      q_last[i] = guide.milestone_configurations[size_t(last)][i];
      mask_last[i] = 1.0;
    }
  // Before it: the approach's last milestone and the stages but the last.
  const auto at = [&](auto& list) { return list.end() - 1; };
  for (int k = first; k < last; ++k) {
    const GuideMilestone& m = guide.milestones[size_t(k)];
    problem.milestones.insert(at(problem.milestones), guide.milestone_configurations[size_t(k)]);
    problem.milestone_masks.insert(at(problem.milestone_masks), stated_entries(system, m));
    problem.milestone_tolerances.insert(at(problem.milestone_tolerances), 0.0);
    problem.milestone_contact_pairs.insert(at(problem.milestone_contact_pairs), m.contacts);
  }
}

std::optional<ComputedGuide> complete_written_guide(Problem& problem, const GuideOptions& options) {
  const std::vector<int> unstated = unstated_moving_roots(problem);
  const bool no_joints = states_no_joints(problem) && keeps_and_adds(problem);
  if (unstated.empty() && !no_joints) return std::nullopt;
  ComputedGuide guide = compute_guide(problem, options);
  const bool posture_change =
      no_joints && guide.status == GuideStatus::Computed && guide.stages > 0;
  if (unstated.empty() && !posture_change) return std::nullopt;
  if (guide.status == GuideStatus::Computed) complete_milestones(problem, guide, unstated);
  if (posture_change) complete_posture_change(problem, guide);
  guide.completed = unstated;
  guide.completed_posture_change = posture_change;
  return guide;
}

}  // namespace stanceplan
