#pragma once
// The curvature of the joint torques (E18-E19): H += Hessian of sum_e w_e^T tau_e(x), with w_e
// collected in state.torque_weights by the torque-limit rows (y_k / effort_k) and the objective
// (E24: 2 w3 tau). Convention of joint_torques.h: tau + sum_loads J(p)^T F = 0, gravity a load
// m g at every link's centre of mass, so
//   w^T tau = -M g . v_C(w) - sum_loads F . v_p(w),
// with v the velocity of the load point (or the centre of mass) when the joints move at rates w.
// Each load contributes the point velocity's curvature (third-order kinematics), the force's
// (its generators turn with s2's link) and the products of their first derivatives.
#include <Eigen/Core>

#include "planner/solver/nlp_state.h"

namespace stanceplan {

void add_weighted_torque_hessian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> H);

}  // namespace stanceplan
