#pragma once
// The guide's goal configuration (docs/METHOD.md section 3, "The guide computed"): a posture of
// the goal stance with every contact loaded, solved by the IK-statics program (section 4) from the
// initial configuration carried towards the goal contacts.
#include <Eigen/Core>

#include "planner/plan/problem.h"
#include "planner/solver/posture_result.h"

namespace stanceplan {

// The initial configuration with every floating root (robot or object) moved rigidly towards the
// goal contacts it takes part in that are new or placed: each such contact's own surface origin
// aims at the other surface's stated placement point, else at its polygon's centroid. The root is
// turned about the vertical by the mean change of heading of the placed surfaces (a walk with a
// turn ends facing its goal placements) and translated by the mean displacement of the surface
// origins; an object pulled by three or more contacts whose origins span a plane is turned by the
// rotation that best carries the origins onto their targets (a ball turned over in the hand).
// Contacts the initial stance already has, unplaced, pull nowhere (feet that may stay).
Eigen::VectorXd carried_configuration(const Problem& problem);

// A posture of the goal stance, every contact loaded, from and pulled towards
// carried_configuration(). With infeasibility diagnosis (the `posture` command's reason).
PostureResult solve_goal_posture(const Problem& problem);

}  // namespace stanceplan
