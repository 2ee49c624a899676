#pragma once
// The straight path between two system configurations that motions are projected from: joints
// and root positions linearly, root orientations along the shorter great arc (slerp), so that
// every interpolated quaternion is a unit one.
#include <Eigen/Core>

#include "planner/model/system.h"

namespace stanceplan {

// q_out = q(s) on the path from q_a (s = 0) to q_b (s = 1). q_out must have System::nq() entries
// (nothing is allocated).
void interpolate_configuration(const System& system, const Eigen::VectorXd& q_a,
                               const Eigen::VectorXd& q_b, double s, Eigen::VectorXd& q_out);

}  // namespace stanceplan
