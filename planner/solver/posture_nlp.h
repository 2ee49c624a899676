#pragma once
// The IK-statics program of one request, assembled from named constraint blocks, as flat arrays
// in the shape every NLP solver wants (n, m, bounds, sparse Jacobian triplets). Independent of
// Ipopt: the adapter (ipopt_adapter.cpp) and the tests both drive it.
#include <memory>
#include <vector>

#include "planner/solver/constraint_block.h"
#include "planner/solver/hessian_cache.h"
#include "planner/solver/objective.h"

namespace stanceplan {

// The starting point of the program at the state's request: q_init and, for every loaded contact,
// its force guess or an even share of the weight (leaves the state at that point).
Eigen::VectorXd make_starting_point(NlpState& state);

class PostureNlp {
 public:
  // active_pairs: indices into scene.collision->pairs() that enter the program (E20), with the
  // least distance each must keep (default: options.collision_margin).
  // torque_dofs: per entity, the dofs whose E19 rows enter (PostureSolver's torque active set);
  // nullptr: every dof with an effort limit.
  // polygon_rows: per contact, the rows of its PolygonBlock that enter (the polygon active set);
  // nullptr: every row.
  PostureNlp(const Scene& scene, const PostureRequest& request, const SolverOptions& options,
             std::vector<int> active_pairs, std::vector<double> pair_bounds = {},
             HessianCache* hessian_cache = nullptr,
             const std::vector<std::vector<int>>* torque_dofs = nullptr,
             const std::vector<std::vector<int>>* polygon_rows = nullptr);

  int n() const { return layout_.n; }
  int m() const { return m_; }
  int nnz() const { return static_cast<int>(rows_.size()); }
  const NlpLayout& layout() const { return layout_; }
  NlpState& state() { return state_; }
  const std::vector<std::unique_ptr<ConstraintBlock>>& blocks() const { return blocks_; }
  int block_first_row(int b) const { return first_row_[b]; }

  void variable_bounds(double* lower, double* upper) const;  // E6 joint limits, E7 lambda >= 0
  void constraint_bounds(double* lower, double* upper) const;
  void structure(int* rows, int* cols) const;
  void starting_point(double* x) const;

  // `new_x` false promises that x equals the previous call's x (Ipopt's convention).
  double objective(const double* x, bool new_x);
  void objective_gradient(const double* x, bool new_x, double* grad);
  void constraints(const double* x, bool new_x, double* g);
  void jacobian_values(const double* x, bool new_x, double* values);
  // Hessian of the Lagrangian obj_factor f + y^T g, lower triangle (i >= j), the entries that
  // can be nonzero (hessian_groups.h) in row-major order. See HessianMode::FiniteDifference.
  int hessian_nnz() const { return hessian_ ? static_cast<int>(hessian_->rows.size()) : 0; }
  const HessianGroups& hessian_groups() const { return hessian_->groups; }
  void hessian_structure(int* rows, int* cols) const;
  void hessian_values(const double* x, bool new_x, double obj_factor, const double* y,
                      double* values);
  // The whole Hessian (n x n, both triangles) left by the last hessian_values, for tests.
  const Eigen::MatrixXd& dense_hessian() const { return H_; }
  // The dense Jacobian (m x n), for tests.
  const Eigen::MatrixXd& dense_jacobian(const double* x, bool new_x);

 private:
  void update(const double* x, bool new_x);

  NlpLayout layout_;
  NlpState state_;
  Objective objective_;
  std::vector<std::unique_ptr<ConstraintBlock>> blocks_;
  std::vector<int> first_row_;
  int m_ = 0;
  std::vector<int> rows_, cols_;
  // Gradient of the Lagrangian at the state's current x.
  void lagrangian_gradient(double obj_factor, const Eigen::Ref<const Eigen::VectorXd>& y,
                           Eigen::Ref<Eigen::VectorXd> out);
  void lagrangian_gradient(NlpState& state, double obj_factor,
                           const Eigen::Ref<const Eigen::VectorXd>& y,
                           Eigen::Ref<Eigen::VectorXd> out);
  PostureRequest generic_request(const Eigen::VectorXd& q, int seed) const;

  void analytic_hessian_values(const double* x, bool new_x, double obj_factor, const double* y,
                               double* values);
  void probe_point(int seed, Eigen::VectorXd* x, Eigen::VectorXd* y) const;
  std::shared_ptr<const HessianStructure> measure_hessian_structure();
  std::shared_ptr<const HessianStructure> measure_analytic_structure();
  void analytic_hessian(NlpState& state, double obj_factor,
                        const Eigen::Ref<const Eigen::VectorXd>& y,
                        Eigen::Ref<Eigen::MatrixXd> H) const;
  HessianCache::Key hessian_key() const;
  std::vector<std::vector<int>> torque_dofs_;
  std::vector<std::vector<int>> polygon_rows_;  // empty: all

  std::shared_ptr<const HessianStructure> hessian_;
  Eigen::VectorXd x0_;  // the starting point
  Eigen::MatrixXd J_;
  Eigen::MatrixXd H_;
  Eigen::VectorXd grad_, grad_step_, x_step_;
  bool has_x_ = false;
};

}  // namespace stanceplan
