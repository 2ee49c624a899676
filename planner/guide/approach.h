#pragma once
// The goal approached in the initial posture (docs/METHOD.md section 3, "The guide computed"): a
// robot that changes its posture at the goal (sits down) first walks there as it stands, then
// changes posture where its feet already are. Without it the path's straight lines lower a
// walking robot's base while it still walks (the guide-free desk: the base 0.2 m lower halfway
// through the side-step into the chair, milestones no stance on the feet reaches).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/plan/problem.h"

namespace stanceplan {

struct Approach {
  // The goal posture with every floating robot that keeps a contact of the initial stance into the
  // goal (feet on the floor) back in its initial joints (see limbs_only below), its root moved
  // rigidly over the ground (turned about the vertical, translated) so that the surfaces of those
  // kept contacts are where the goal posture has them (their mean position and heading).
  Eigen::VectorXd q;
  // The kept contacts, "entity/surface" pairs: the contacts offered on the way to q.
  std::vector<std::pair<std::string, std::string>> kept;
  std::vector<int> robots;  // the robots that approach (entity indices)
  double back_off = 0.0;    // m: how far short of the goal's footholds (see below)
  bool limbs_only = false;  // whether the arms keep the goal posture's (see below)
};

// The approach is tried backed off by up to kMaxBackOff, every kBackOffStep (m).
inline constexpr double kMaxBackOff = 0.4;
inline constexpr double kBackOffStep = 0.02;

// Largest joint change (rad) between the initial and the goal posture below which a robot needs no
// approach: its goal posture is its initial one carried (a walk, a side-step).
inline constexpr double kPostureChange = 0.3;

// The approach configuration; nullopt when no floating robot keeps a contact and changes a joint
// by more than kPostureChange. `limbs_only`: only the joints between the root and the kept
// surfaces (the legs) are the initial ones, the others (arms, chest) keep the goal posture's (the
// arms laid forward at the desk, raised by the legs' stretch, clear the desk that the initial
// posture's hands, held forward at its edge, would be in). `back_off` (m): the kept surfaces
// that much short of their goal place, horizontally towards the goal posture's base (a seated
// robot's feet are under the desk, where it cannot stand: it stands in front of the seat).
std::optional<Approach> approach_configuration(const Problem& problem,
                                               const Eigen::VectorXd& q_goal,
                                               bool limbs_only = false, double back_off = 0.0);

}  // namespace stanceplan
