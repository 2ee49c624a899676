#pragma once
// Whether a held rigid object can still balance once a contact is removed: a cheap test before a
// removal's solve (docs/METHOD.md section 3, "Ordering"). The object is a floating entity without
// joints and with mass (the hand-over's cylinder, the ball, the pen, the table); its other contacts
// keep their placements on it, so at the node's configuration only forces can change: the test
// asks whether forces in the linearised friction cones (E5) at those contacts' points balance its
// weight (E16-E17, the object alone), by nonnegative least squares over the cone generators.
//
// What it cannot tell: a removal's solve may also move the holders and so turn the object (a pad
// on a standing cylinder's side becomes a pad under it once the arm turns it over), so a failed
// test is a prediction, not a proof. The search defers such a removal to backtracking
// (SearchOptions::defer_unbalanced_removals); it never prunes one. A robot (joints) is never
// tested: its centre of mass moves over the kept supports in the solve (every step of a walk would
// fail).
#include <Eigen/Core>
#include <vector>

#include "planner/contact/contact.h"
#include "planner/model/model_data.h"
#include "planner/scene/scene.h"

namespace stanceplan {

// Lawson and Hanson's active-set method (Solving Least Squares Problems, 1974, chapter 23):
// x >= 0 minimising |A x - b|. Returns that least residual |A x - b|.
double nonnegative_least_squares(const Eigen::MatrixXd& A, const Eigen::VectorXd& b,
                                 Eigen::VectorXd* x);

// False when some rigid object that `removed` touches (not a robot, not fixed, with mass) keeps
// contacts in `stance` (other than `removed`), none bilateral, whose cone forces at `data` (every
// entity's kinematics at the node) cannot hold its weight to within `tolerance` of it. True
// otherwise (no such object; a bilateral contact holds any load; the search's own rule already
// keeps the last contact of a floating body).
bool objects_balance_without(const Scene& scene, const std::vector<ModelData>& data,
                             const Stance& stance, const Contact& removed, double friction,
                             int cone_generators, double tolerance = 1e-3);

}  // namespace stanceplan
