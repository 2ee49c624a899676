#pragma once
// The constraint families of the IK-statics program (docs/METHOD.md section 4), one class per
// family, each implemented in its own file.
#include <memory>
#include <vector>

#include "planner/collision/signed_distance.h"
#include "planner/solver/constraint_block.h"

namespace stanceplan {

// |phi|^2 = 1 for the root quaternion of every floating robot and object.
class QuaternionNormBlock : public ConstraintBlock {
 public:
  explicit QuaternionNormBlock(const System& system);
  int rows() const override { return static_cast<int>(entities_.size()); }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override;
  void row_columns(int r, std::vector<int>* columns) const override;
  void evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                   Eigen::Ref<Eigen::MatrixXd> H) const override;

 private:
  const System& system_;
  std::vector<int> entities_;
};

// E8-E13 for one contact: normals opposed (2 rows + a branch inequality), s1's origin on s2's
// plane, and for a fixed placement the position (x_c, y_c) and orientation theta_c (1 row + a
// branch inequality). A free placement (case 1) keeps only the first three rows and the branch.
// A point contact (s1 a point surface) has E9 with the sphere's centre r above s2's plane and,
// fixed, E10-E11: 1 or 3 rows.
class ContactGeometryBlock : public ConstraintBlock {
 public:
  int contact() const override { return task_; }
  ContactGeometryBlock(const NlpState& state, int task);
  int rows() const override { return point_ ? (fixed_ ? 3 : 1) : (fixed_ ? 8 : 4); }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override;
  void row_columns(int r, std::vector<int>* columns) const override;
  void evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                   Eigen::Ref<Eigen::MatrixXd> H) const override;

 private:
  int row_e9() const;  // the local rows of E9, E10 and E11
  int row_e10() const;
  int row_e11() const;

  int task_;
  bool fixed_;
  bool point_ = false;
  double radius_ = 0.0;
  Placement placement_;
  double standoff_ = 0.0;  // E9 bound: s1 held this far above s2 (ContactTask::standoff)
  std::vector<int> columns_;
};

// Case 1 relaxation of E10-E11: every vertex of s1 inside s2's convex polygon, as linear
// inequalities in s2's plane (one per vertex of s1 and edge of s2, row j * edges + e). `only`: the
// rows that enter (PostureSolver's polygon active set); nullptr: every row.
class PolygonBlock : public ConstraintBlock {
 public:
  int contact() const override { return task_; }
  PolygonBlock(const NlpState& state, int task, const std::vector<int>* only = nullptr);
  int rows() const override { return static_cast<int>(rows_.size()); }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override;
  void row_columns(int r, std::vector<int>* columns) const override;
  void evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                   Eigen::Ref<Eigen::MatrixXd> H) const override;

 private:
  struct Row {
    int vertex, edge;
  };
  int task_;
  std::vector<Row> rows_;
  std::vector<Eigen::Vector2d> edge_normals_;  // inward unit normals of s2's edges, s2's plane
  std::vector<double> edge_offsets_;           // n_e . a_e
  std::vector<int> columns_;
};

// E16-E17: static equilibrium of one floating robot or object, divided by m |g| so that the rows
// are dimensionless: sum of received forces + m g = 0, sum of their moments about the world
// origin + C x m g = 0.
class EquilibriumBlock : public ConstraintBlock {
 public:
  EquilibriumBlock(const NlpState& state, int entity);
  int rows() const override { return 6; }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override;
  void row_columns(int r, std::vector<int>* columns) const override;
  void evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                   Eigen::Ref<Eigen::MatrixXd> H) const override;

 private:
  struct Received {
    int task, vertex;
    double sign;  // +1 as s1's entity, -1 as s2's entity
  };
  int entity_;
  double scale_;  // 1 / (m |g|)
  std::vector<Received> received_;
  std::vector<int> columns_;
};

// E18-E19: -1 <= tau_k / effort_k <= 1 for every dof of one robot with an effort limit (or, with
// `only`, for those of the listed dofs that have one: PostureSolver's torque active set).
class TorqueLimitBlock : public ConstraintBlock {
 public:
  TorqueLimitBlock(const NlpState& state, int entity, const std::vector<int>* only = nullptr);
  int rows() const override { return static_cast<int>(dofs_.size()); }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override;
  void row_columns(int r, std::vector<int>* columns) const override;
  void evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                   Eigen::Ref<Eigen::MatrixXd> H) const override;
  bool empty() const { return dofs_.empty(); }

 private:
  int entity_;
  std::vector<int> dofs_;
  std::vector<double> efforts_;
  std::vector<int> columns_;
};

// E20: signed distance >= margin for every active pair of links (E48 for the gradient).
class CollisionBlock : public ConstraintBlock {
 public:
  // lower_bounds[i]: the least signed distance pair i must keep.
  CollisionBlock(const NlpState& state, std::vector<int> pairs, std::vector<double> lower_bounds);
  int rows() const override { return static_cast<int>(pairs_.size()); }
  void bounds(Eigen::Ref<Eigen::VectorXd> lower, Eigen::Ref<Eigen::VectorXd> upper) const override;
  void row_columns(int r, std::vector<int>* columns) const override;
  void evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const override;
  void jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const override;
  void add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                   Eigen::Ref<Eigen::MatrixXd> H) const override;

 private:
  void update(NlpState& state) const;  // distances at the state's current x

  const System& system_;
  const CollisionModel& model_;
  std::vector<int> pairs_;
  std::vector<double> lower_bounds_;
  mutable CollisionData work_;
  mutable std::vector<DistanceResult> results_;
  mutable Eigen::VectorXd x_of_results_;
  mutable Eigen::RowVectorXd gradient_;
};

}  // namespace stanceplan
