#include "planner/solver/posture_nlp.h"

#include <algorithm>
#include <cmath>

#include "planner/solver/blocks/blocks.h"

namespace stanceplan {

PostureNlp::PostureNlp(const Scene& scene, const PostureRequest& request,
                       const SolverOptions& options, std::vector<int> active_pairs,
                       std::vector<double> pair_bounds)
    : layout_(scene, request, options), state_(scene, request, options, layout_), objective_(state_) {
  const System& system = scene.system;
  auto add = [&](std::unique_ptr<ConstraintBlock> block) {
    if (block->rows() > 0) blocks_.push_back(std::move(block));
  };
  add(std::make_unique<QuaternionNormBlock>(system));
  for (int t = 0; t < static_cast<int>(request.contacts.size()); ++t) {
    add(std::make_unique<ContactGeometryBlock>(state_, t));
    if (!request.contacts[t].placement) add(std::make_unique<PolygonBlock>(state_, t));
  }
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    if (entity.floating() && entity.model->total_mass > 0.0)
      add(std::make_unique<EquilibriumBlock>(state_, e));
    if (options.enforce_torque_limits && entity.kind != EntityKind::Object && entity.model->num_dofs() > 0)
      add(std::make_unique<TorqueLimitBlock>(state_, e));
  }
  if (pair_bounds.size() != active_pairs.size()) pair_bounds.assign(active_pairs.size(), options.collision_margin);
  if (scene.collision && options.enforce_collisions && !active_pairs.empty())
    add(std::make_unique<CollisionBlock>(state_, std::move(active_pairs), std::move(pair_bounds)));
  std::vector<int> columns;
  for (const auto& block : blocks_) {
    first_row_.push_back(m_);
    for (int r = 0; r < block->rows(); ++r) {
      columns.clear();
      block->row_columns(r, &columns);
      sort_unique(&columns);
      for (int c : columns) {
        rows_.push_back(m_ + r);
        cols_.push_back(c);
      }
    }
    m_ += block->rows();
  }
  groups_ = make_hessian_groups(system, state_.constants, layout_);
  J_.setZero(m_, layout_.n);
  H_.setZero(layout_.n, layout_.n);
  grad_.setZero(layout_.n);
  grad_step_.setZero(layout_.n);
  x_step_.setZero(layout_.n);
}

void PostureNlp::variable_bounds(double* lower, double* upper) const {
  constexpr double kInf = 1e19;
  std::fill(lower, lower + n(), -kInf);
  std::fill(upper, upper + n(), kInf);
  const System& system = state_.scene.system;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    const Model& model = *entity.model;
    for (int k = 0; k < model.num_dofs(); ++k) {
      const Joint& joint = model.joints[model.dof_joints[k]];
      if (!joint.has_position_limits) continue;
      const int i = system.offset(e) + entity.first_dof() + k;
      lower[i] = joint.lower;  // E6
      upper[i] = joint.upper;
    }
  }
  for (const ForceBlock& block : layout_.forces)
    if (!block.bilateral)
      std::fill(lower + block.first_column, lower + block.first_column + block.size(), 0.0);  // E7
}

void PostureNlp::constraint_bounds(double* lower, double* upper) const {
  for (size_t b = 0; b < blocks_.size(); ++b) {
    const int rows = blocks_[b]->rows();
    blocks_[b]->bounds(Eigen::Map<Eigen::VectorXd>(lower + first_row_[b], rows),
                       Eigen::Map<Eigen::VectorXd>(upper + first_row_[b], rows));
  }
}

void PostureNlp::structure(int* rows, int* cols) const {
  std::copy(rows_.begin(), rows_.end(), rows);
  std::copy(cols_.begin(), cols_.end(), cols);
}

void PostureNlp::starting_point(double* x) const {
  const PostureRequest& request = state_.request;
  Eigen::Map<Eigen::VectorXd> out(x, n());
  out.head(layout_.nq) = request.q_init;
  // Forces: share the weight of every floating body evenly over the loaded vertices, as an
  // interior point (lambda > 0) of the cone coefficients.
  double weight = 0.0;
  for (const Entity& e : state_.scene.system.entities())
    if (e.floating()) weight += e.model->total_mass * state_.scene.gravity.norm();
  int vertices = 0;
  for (const ForceBlock& block : layout_.forces) vertices += block.num_vertices;
  const double per_vertex = vertices > 0 ? weight / vertices : 0.0;
  for (const ForceBlock& block : layout_.forces) {
    auto lambda = out.segment(block.first_column, block.size());
    if (block.bilateral) {
      lambda.setZero();
    } else {
      const double cos_half = 1.0 / std::sqrt(1.0 + state_.options.friction * state_.options.friction);
      lambda.setConstant(std::max(per_vertex / (block.per_vertex * cos_half), 1e-3));
    }
  }
}

void PostureNlp::update(const double* x, bool new_x) {
  if (new_x || !has_x_) state_.set_x(x);
  has_x_ = true;
}

double PostureNlp::objective(const double* x, bool new_x) {
  update(x, new_x);
  return objective_.value(state_);
}

void PostureNlp::objective_gradient(const double* x, bool new_x, double* grad) {
  update(x, new_x);
  objective_.gradient(state_, Eigen::Map<Eigen::VectorXd>(grad, n()));
}

void PostureNlp::constraints(const double* x, bool new_x, double* g) {
  update(x, new_x);
  for (size_t b = 0; b < blocks_.size(); ++b)
    blocks_[b]->evaluate(state_, Eigen::Map<Eigen::VectorXd>(g + first_row_[b], blocks_[b]->rows()));
}

const Eigen::MatrixXd& PostureNlp::dense_jacobian(const double* x, bool new_x) {
  update(x, new_x);
  J_.setZero();
  for (size_t b = 0; b < blocks_.size(); ++b)
    blocks_[b]->jacobian(state_, J_.middleRows(first_row_[b], blocks_[b]->rows()));
  return J_;
}

void PostureNlp::jacobian_values(const double* x, bool new_x, double* values) {
  dense_jacobian(x, new_x);
  for (size_t k = 0; k < rows_.size(); ++k) values[k] = J_(rows_[k], cols_[k]);
}

}  // namespace stanceplan

namespace stanceplan {

void PostureNlp::hessian_structure(int* rows, int* cols) const {
  int k = 0;
  for (int i = 0; i < n(); ++i)
    for (int j = 0; j <= i; ++j) {
      rows[k] = i;
      cols[k] = j;
      ++k;
    }
}

void PostureNlp::lagrangian_gradient(double obj_factor, const Eigen::Ref<const Eigen::VectorXd>& y,
                                     Eigen::Ref<Eigen::VectorXd> out) {
  // Signed distance is only piecewise smooth (its witness features jump, e.g. between parallel
  // faces): differencing its gradient gives meaningless curvature, so collision rows are given
  // none, as in Gauss-Newton. Every other family is smooth.
  J_.setZero();
  for (size_t b = 0; b < blocks_.size(); ++b)
    if (blocks_[b]->family() != "collision")
      blocks_[b]->jacobian(state_, J_.middleRows(first_row_[b], blocks_[b]->rows()));
  objective_.gradient(state_, out);
  out *= obj_factor;
  out.noalias() += J_.transpose() * y;
}

double PostureNlp::symmetric_entry(int i, int j) const {
  const bool ij = groups_.readable(i, j) || groups_.structural_zero(i, j);
  const bool ji = groups_.readable(j, i) || groups_.structural_zero(j, i);
  if (ij && ji) return 0.5 * (H_(i, j) + H_(j, i));
  return ij ? H_(i, j) : H_(j, i);  // make_hessian_groups guarantees one side
}

void PostureNlp::hessian_values(const double* x, bool new_x, double obj_factor, const double* y_in,
                                double* values) {
  update(x, new_x);
  const Eigen::Map<const Eigen::VectorXd> y(y_in, m_);
  const int nq = layout_.nq;
  lagrangian_gradient(obj_factor, y, grad_);
  H_.setZero();
  // Forward differences of the exact gradient along the configuration directions give the q-q
  // block and the lambda-q block (columns k < nq), several columns per evaluation where their
  // entities share no contact (hessian_groups.h).
  auto step = [x](int k) { return 1e-7 * std::max(1.0, std::abs(x[k])); };
  x_step_ = Eigen::Map<const Eigen::VectorXd>(x, n());
  for (const std::vector<int>& group : groups_.groups) {
    for (int k : group) x_step_[k] += step(k);
    state_.set_x(x_step_.data());
    lagrangian_gradient(obj_factor, y, grad_step_);
    for (int k : group) {
      H_.col(k) = (grad_step_ - grad_) / step(k);
      x_step_[k] = x[k];
      if (group.size() == 1) continue;
      for (int i = 0; i < n(); ++i)
        if (groups_.structural_zero(i, k)) H_(i, k) = 0.0;
    }
  }
  state_.set_x(x);  // later calls with new_x = false expect the state at x
  // lambda-lambda: the constraints are linear in lambda; the objective contributes
  // 2 w_force I + 2 w_torque (dtau/dlambda)^T (dtau/dlambda).
  const SolverOptions& o = state_.options;
  const int nl = n() - nq;
  if (nl > 0) {
    auto Hll = H_.bottomRightCorner(nl, nl);
    Hll.diagonal().array() += obj_factor * 2.0 * o.w_force;
    if (o.w_torque > 0.0) {
      state_.ensure_torques();
      for (const Eigen::MatrixXd& D : state_.dtau_dx)
        if (D.size() > 0) Hll.noalias() += obj_factor * 2.0 * o.w_torque * D.rightCols(nl).transpose() * D.rightCols(nl);
    }
  }
  int k = 0;
  for (int i = 0; i < n(); ++i)
    for (int j = 0; j <= i; ++j) {
      // Symmetrise the differenced q-q block; below it, column j < nq of row i >= nq is d/dq_j of
      // the lambda-gradient, exact up to the difference error.
      values[k++] = (i < nq) ? symmetric_entry(i, j) : H_(i, j);
    }
}

}  // namespace stanceplan
