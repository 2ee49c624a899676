#pragma once
// Milestones sampled along the guide path (docs/METHOD.md section 3), in the form the search reads
// from a scenario's `guide:` section: partial milestones stating the pose of each moving root
// (its position; an object's orientation too when it turns between the two postures), nothing
// else. No joint angles (the solver's reference keeps the initial posture, as in the untuned
// scenarios) and no per-milestone contacts: the search offers search.contact_pairs at every
// milestone, and its candidate pruning (contact_reach) already keeps the surfaces out of reach
// out of it.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "planner/guide/guide_space.h"

namespace stanceplan {

struct GuideMilestone {
  struct Root {
    int entity = -1;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    std::optional<Eigen::Vector3d> rpy;  // roll, pitch, yaw (rad), as the scenario's base_rpy
  };
  std::vector<Root> roots;
};

// Points of the space every `spacing` of travel along the waypoints (GuideSpace::travel; spaced
// evenly, at least one: the last is the goal).
std::vector<Eigen::VectorXd> points_along(const GuideSpace& space,
                                          const std::vector<Eigen::VectorXd>& waypoints,
                                          double spacing);

// The milestone at a point of the space.
GuideMilestone milestone_at(const GuideSpace& space, const Eigen::VectorXd& x);

}  // namespace stanceplan
