#include "planner/solver/blocks/blocks.h"

namespace stanceplan {

QuaternionNormBlock::QuaternionNormBlock(const System& system)
    : ConstraintBlock("quaternion"), system_(system) {
  for (int e = 0; e < system.num_entities(); ++e)
    if (system.entity(e).floating()) entities_.push_back(e);
}

void QuaternionNormBlock::bounds(Eigen::Ref<Eigen::VectorXd> lower,
                                 Eigen::Ref<Eigen::VectorXd> upper) const {
  lower.setOnes();
  upper.setOnes();
}

void QuaternionNormBlock::row_columns(int r, std::vector<int>* columns) const {
  const int first = system_.offset(entities_[r]) + Entity::kBaseQuaternion;
  for (int i = 0; i < 4; ++i) columns->push_back(first + i);
}

void QuaternionNormBlock::evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const {
  for (int r = 0; r < rows(); ++r)
    g[r] = state.x.segment<4>(system_.offset(entities_[r]) + Entity::kBaseQuaternion).squaredNorm();
}

void QuaternionNormBlock::jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const {
  for (int r = 0; r < rows(); ++r) {
    const int first = system_.offset(entities_[r]) + Entity::kBaseQuaternion;
    J.row(r).segment<4>(first) = 2.0 * state.x.segment<4>(first).transpose();
  }
}

void QuaternionNormBlock::add_hessian(NlpState&, const Eigen::Ref<const Eigen::VectorXd>& y,
                                      Eigen::Ref<Eigen::MatrixXd> H) const {
  for (int r = 0; r < rows(); ++r) {
    const int first = system_.offset(entities_[r]) + Entity::kBaseQuaternion;
    H.block<4, 4>(first, first).diagonal().array() += 2.0 * y[r];
  }
}

}  // namespace stanceplan
