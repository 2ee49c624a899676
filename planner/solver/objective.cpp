#include "planner/solver/objective.h"

#include "planner/solver/hessian_terms.h"

#include <cmath>

namespace stanceplan {

Objective::Objective(const NlpState& state) {
  q_ref_ = state.request.q_ref.size() > 0 ? state.request.q_ref : state.request.q_init;
  for (int t = 0; t < static_cast<int>(state.request.contacts.size()); ++t) {
    const ContactTask& task = state.request.contacts[t];
    if (!task.placement && task.placement_target) targeted_tasks_.push_back(t);
  }
}

double Objective::value(NlpState& state) const {
  const SolverOptions& o = state.options;
  const int nq = state.layout.nq;
  double f = o.w_configuration * (state.x.head(nq) - q_ref_).squaredNorm();  // E22
  f += o.w_force * state.x.tail(state.layout.n - nq).squaredNorm();          // E23
  if (o.w_torque > 0.0) {
    state.ensure_torque_values();
    for (const Eigen::VectorXd& tau : state.tau) f += o.w_torque * tau.squaredNorm();  // E24
  }
  for (int t : targeted_tasks_) {  // E25 (obj4)
    const ContactFrames& fr = state.frames[t];
    const Placement& target = *state.request.contacts[t].placement_target;
    const Eigen::Vector3d d = fr.O1 - fr.O2;
    f += o.w_placement *
         (std::pow(d.dot(fr.x2) - target.x, 2) + std::pow(d.dot(fr.y2) - target.y, 2));
  }
  return f;
}

void Objective::gradient(NlpState& state, Eigen::Ref<Eigen::VectorXd> grad) const {
  const SolverOptions& o = state.options;
  const int nq = state.layout.nq;
  grad.setZero();
  grad.head(nq) = 2.0 * o.w_configuration * (state.x.head(nq) - q_ref_);
  grad.tail(state.layout.n - nq) = 2.0 * o.w_force * state.x.tail(state.layout.n - nq);
  if (o.w_torque > 0.0) {
    state.ensure_torques();
    for (size_t e = 0; e < state.tau.size(); ++e)
      if (state.tau[e].size() > 0)
        grad.noalias() += (2.0 * o.w_torque) * state.dtau_dx[e].transpose() * state.tau[e];
  }
  if (targeted_tasks_.empty()) return;
  state.ensure_jacobians();
  Eigen::Map<Eigen::RowVectorXd> row(grad.data(), grad.size());
  for (int t : targeted_tasks_) {
    const ContactFrames& fr = state.frames[t];
    const ContactConstants& k = state.constants[t];
    const Placement& target = *state.request.contacts[t].placement_target;
    const Eigen::Vector3d d = fr.O1 - fr.O2;
    const double ex = 2.0 * o.w_placement * (d.dot(fr.x2) - target.x);
    const double ey = 2.0 * o.w_placement * (d.dot(fr.y2) - target.y);
    const Eigen::Vector3d c = ex * fr.x2 + ey * fr.y2;  // d/dd of the two squares
    state.add_entity_term(k.e1, fr.J_O1, c, row);
    state.add_entity_term(k.e2, fr.J_O2, -c, row);
    state.add_entity_term(k.e2, fr.J_x2, ex * d, row);
    state.add_entity_term(k.e2, fr.J_y2, ey * d, row);
  }
}

void Objective::add_hessian(NlpState& state, double factor, Eigen::Ref<Eigen::MatrixXd> H) const {
  const SolverOptions& o = state.options;
  const int nq = state.layout.nq, n = state.layout.n;
  H.diagonal().head(nq).array() += factor * 2.0 * o.w_configuration;  // E22
  H.diagonal().tail(n - nq).array() += factor * 2.0 * o.w_force;      // E23
  if (o.w_torque > 0.0) {                                             // E24
    state.ensure_torques();
    // 2 w3 (dtau/dx)^T (dtau/dx): its lower triangle by rank updates (half the product), mirrored.
    Eigen::MatrixXd& gram = state.torque_gram;
    gram.setZero();
    for (size_t e = 0; e < state.tau.size(); ++e) {
      if (state.tau[e].size() == 0) continue;
      state.torque_weights[e] += (factor * 2.0 * o.w_torque) * state.tau[e];
      gram.selfadjointView<Eigen::Lower>().rankUpdate(state.dtau_dx[e].transpose(),
                                                      factor * 2.0 * o.w_torque);
    }
    H.triangularView<Eigen::Lower>() += gram;
    H.triangularView<Eigen::StrictlyUpper>() += gram.transpose();
  }
  if (targeted_tasks_.empty()) return;
  state.ensure_jacobians();
  // E25: w4 (s_x^2 + s_y^2), s = (O1 - O2) . x2 - target: 2 w4 (grad s grad s^T + s Hess s).
  RowRef row(state.gradient_scratch);
  for (int t : targeted_tasks_) {
    const ContactFrames& fr = state.frames[t];
    const ContactConstants& k = state.constants[t];
    const Placement& target = *state.request.contacts[t].placement_target;
    const Eigen::Vector3d d = fr.O1 - fr.O2;
    const double scale = factor * 2.0 * o.w_placement;
    for (int axis = 0; axis < 2; ++axis) {
      const Eigen::Vector3d& b = axis == 0 ? fr.x2 : fr.y2;
      const Eigen::MatrixXd& J_b = axis == 0 ? fr.J_x2 : fr.J_y2;
      const double s = d.dot(b) - (axis == 0 ? target.x : target.y);
      state.gradient_scratch.setZero();
      state.add_entity_term(k.e1, fr.J_O1, b, row);
      state.add_entity_term(k.e2, fr.J_O2, -b, row);
      state.add_entity_term(k.e2, J_b, d, row);
      H.noalias() += scale * state.gradient_scratch.transpose() * state.gradient_scratch;
      add_offset_dot_curvature(state, t, fr.O1, fr.J_O1, b, J_b, scale * s, H);
    }
  }
}

}  // namespace stanceplan
