#include <algorithm>

#include "planner/solver/blocks/blocks.h"

namespace stanceplan {

TorqueLimitBlock::TorqueLimitBlock(const NlpState& state, int entity, const std::vector<int>* only)
    : ConstraintBlock("torque_limits"), entity_(entity) {
  const System& system = state.scene.system;
  const Model& model = *system.entity(entity).model;
  for (int k = 0; k < model.num_dofs(); ++k) {
    const double effort = model.joints[model.dof_joints[k]].effort;
    if (effort <= 0.0) continue;  // no effort limit given in the URDF
    if (only && std::find(only->begin(), only->end(), k) == only->end()) continue;
    dofs_.push_back(k);
    efforts_.push_back(effort);
  }
  append_entity_columns(system, entity, &columns_);
  append_loaded_contact_columns(state, entity, &columns_);
  sort_unique(&columns_);
}

void TorqueLimitBlock::bounds(Eigen::Ref<Eigen::VectorXd> lower,
                              Eigen::Ref<Eigen::VectorXd> upper) const {
  lower.setConstant(-1.0);  // E19, as a fraction of the URDF effort limit
  upper.setConstant(1.0);
}

void TorqueLimitBlock::row_columns(int, std::vector<int>* columns) const {
  columns->insert(columns->end(), columns_.begin(), columns_.end());
}

void TorqueLimitBlock::evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const {
  state.ensure_torque_values();
  for (int r = 0; r < rows(); ++r) g[r] = state.tau[entity_][dofs_[r]] / efforts_[r];
}

void TorqueLimitBlock::jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const {
  state.ensure_torques();
  for (int r = 0; r < rows(); ++r) J.row(r) = state.dtau_dx[entity_].row(dofs_[r]) / efforts_[r];
}

// The rows' curvature is that of w^T tau with w_k = y_k / effort_k: collected in the state and
// added in one pass over the loads together with the objective's torque term (torque_hessian.h).
void TorqueLimitBlock::add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                                   Eigen::Ref<Eigen::MatrixXd>) const {
  for (int r = 0; r < rows(); ++r) state.torque_weights[entity_][dofs_[r]] += y[r] / efforts_[r];
}

}  // namespace stanceplan
