#include <algorithm>

#include "planner/solver/blocks/blocks.h"

namespace stanceplan {

CollisionBlock::CollisionBlock(const NlpState& state, std::vector<int> pairs,
                               std::vector<double> lower_bounds)
    : ConstraintBlock("collision"),
      system_(state.scene.system),
      model_(*state.scene.collision),
      pairs_(std::move(pairs)),
      lower_bounds_(std::move(lower_bounds)),
      work_(state.scene.system, *state.scene.collision),
      results_(pairs_.size()),
      gradient_(state.scene.system.nq()) {}

void CollisionBlock::bounds(Eigen::Ref<Eigen::VectorXd> lower,
                            Eigen::Ref<Eigen::VectorXd> upper) const {
  for (int r = 0; r < rows(); ++r) lower[r] = lower_bounds_[r];  // E20
  upper.setConstant(1e19);
}

void CollisionBlock::row_columns(int r, std::vector<int>* columns) const {
  const GradientBlocks blocks = gradient_blocks(system_, model_, pairs_[r]);
  for (int b = 0; b < blocks.count; ++b)
    for (int i = 0; i < blocks.size[b]; ++i) columns->push_back(blocks.offset[b] + i);
}

void CollisionBlock::update(NlpState& state) const {
  if (x_of_results_.size() == state.x.size() && x_of_results_ == state.x) return;
  work_.update(model_, state.data);
  for (size_t i = 0; i < pairs_.size(); ++i)
    results_[i] = signed_distance(model_, work_, pairs_[i]);
  x_of_results_ = state.x;
}

void CollisionBlock::evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const {
  update(state);
  for (int r = 0; r < rows(); ++r) g[r] = results_[r].distance;
}

void CollisionBlock::jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const {
  update(state);
  for (int r = 0; r < rows(); ++r) {
    signed_distance_gradient(system_, state.data, model_, pairs_[r], results_[r], work_, gradient_);
    J.row(r).head(system_.nq()) = gradient_;  // E48
  }
}

// Signed distance is only piecewise smooth (its witness features jump, e.g. between parallel
// faces): its rows get no curvature, as in Gauss-Newton.
void CollisionBlock::add_hessian(NlpState&, const Eigen::Ref<const Eigen::VectorXd>&,
                                 Eigen::Ref<Eigen::MatrixXd>) const {}

}  // namespace stanceplan
