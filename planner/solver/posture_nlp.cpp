#include "planner/solver/posture_nlp.h"

#include <algorithm>
#include <cmath>

#include "planner/solver/blocks/blocks.h"

namespace stanceplan {

PostureNlp::PostureNlp(const Scene& scene, const PostureRequest& request,
                       const SolverOptions& options, std::vector<int> active_pairs)
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
  if (scene.collision && options.enforce_collisions && !active_pairs.empty())
    add(std::make_unique<CollisionBlock>(state_, std::move(active_pairs), options.collision_margin));
  std::vector<int> columns;
  for (const auto& block : blocks_) {
    first_row_.push_back(m_);
    for (int r = 0; r < block->rows(); ++r) {
      columns.clear();
      block->row_columns(r, &columns);
      std::sort(columns.begin(), columns.end());
      columns.erase(std::unique(columns.begin(), columns.end()), columns.end());
      for (int c : columns) {
        rows_.push_back(m_ + r);
        cols_.push_back(c);
      }
    }
    m_ += block->rows();
  }
  J_.setZero(m_, layout_.n);
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
