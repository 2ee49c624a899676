#include "planner/solver/objective.h"

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
  f += o.w_force * state.x.tail(state.layout.n - nq).squaredNorm();         // E23
  if (o.w_torque > 0.0) {
    state.ensure_torque_values();
    for (const Eigen::VectorXd& tau : state.tau) f += o.w_torque * tau.squaredNorm();  // E24
  }
  for (int t : targeted_tasks_) {  // E25 (obj4)
    const ContactFrames& fr = state.frames[t];
    const Placement& target = *state.request.contacts[t].placement_target;
    const Eigen::Vector3d d = fr.O1 - fr.O2;
    f += o.w_placement * (std::pow(d.dot(fr.x2) - target.x, 2) + std::pow(d.dot(fr.y2) - target.y, 2));
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

}  // namespace stanceplan
