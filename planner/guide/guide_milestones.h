#pragma once
// Milestones sampled along the guide path (docs/METHOD.md section 3), in the form the search reads
// from a scenario's `guide:` section: partial milestones stating the pose of each moving root
// (its position; an object's orientation too when it turns between the two postures), nothing
// else, but for the goal milestone, which states the robots' joints of the goal posture, the
// approach's milestones (approach.h), which offer the contacts kept from the initial stance only
// (the last one, where the robot stands to change its posture, states its heading too), and the
// posture change's stages (posture_stages.h), which state their whole posture (heading and joints)
// and offer their stance's contacts (the goal stage: every pair). Elsewhere the search offers
// search.contact_pairs, and its candidate pruning (contact_reach) already keeps the surfaces out of
// reach out of it.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/guide/guide_space.h"

namespace stanceplan {

struct GuideMilestone {
  struct Root {
    int entity = -1;
    Eigen::Vector3d position = Eigen::Vector3d::Zero();
    std::optional<Eigen::Vector3d> rpy;  // roll, pitch, yaw (rad), as the scenario's base_rpy
    // A robot's joint angles (rad, in the order of its dofs), stated by the goal milestone only:
    // the solver's reference there is the goal posture (a seated robot is not pulled towards its
    // standing legs).
    std::optional<Eigen::VectorXd> joints;
  };
  std::vector<Root> roots;
  // The contact pairs offered while the milestone is the target ("entity/surface" patterns, as a
  // scenario's milestone `contacts:`); empty: search.contact_pairs. The approach's milestones
  // state the contacts kept from the initial stance (approach.h), the stages theirs
  // (posture_stages.h), the hand-over's the grasps (hand_over.h).
  std::vector<std::pair<std::string, std::string>> contacts;
};

// Points of the space every `spacing` of travel along the waypoints (GuideSpace::travel; spaced
// evenly, at least one: the last is the goal).
std::vector<Eigen::VectorXd> points_along(const GuideSpace& space,
                                          const std::vector<Eigen::VectorXd>& waypoints,
                                          double spacing);

// The milestone at a point of the space.
GuideMilestone milestone_at(const GuideSpace& space, const Eigen::VectorXd& x);

// A root's orientation as the scenario's base_rpy (roll, pitch, yaw: R = Rz(yaw) Ry(pitch)
// Rx(roll)) from its quaternion (w, x, y, z) in a configuration.
Eigen::Vector3d base_rpy(const Eigen::Vector4d& wxyz);

}  // namespace stanceplan
