#pragma once
// E21-E25: w1 ||q - q_ref||^2 + w2 ||lambda||^2 + w3 ||tau||^2 + w4 obj4, where obj4 pulls the
// origin of every free-placement contact's s1 towards its target (x, y) in s2's plane.
#include <Eigen/Core>

#include "planner/solver/nlp_state.h"

namespace stanceplan {

class Objective {
 public:
  explicit Objective(const NlpState& state);
  double value(NlpState& state) const;
  void gradient(NlpState& state, Eigen::Ref<Eigen::VectorXd> grad) const;
  // H += factor * Hessian (n x n, both triangles). The torque term's curvature through tau's own
  // second derivatives is left in state.torque_weights (torque_hessian.h); its Gauss-Newton part
  // 2 w3 (dtau/dx)^T (dtau/dx) is added here.
  void add_hessian(NlpState& state, double factor, Eigen::Ref<Eigen::MatrixXd> H) const;

 private:
  Eigen::VectorXd q_ref_;
  std::vector<int> targeted_tasks_;
};

}  // namespace stanceplan
