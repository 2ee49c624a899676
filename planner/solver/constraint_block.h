#pragma once
// A named family of constraint rows of the IK-statics program (ifopt style): each block declares
// its rows' bounds and sparsity and fills its own values and Jacobian rows. The family name is
// what residual reports and infeasibility messages use.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "planner/solver/nlp_state.h"

namespace stanceplan {

class ConstraintBlock {
 public:
  explicit ConstraintBlock(std::string family) : family_(std::move(family)) {}
  virtual ~ConstraintBlock() = default;

  const std::string& family() const { return family_; }
  // The request contact this block constrains (contact_geometry, polygon), or -1: residual reports
  // name it.
  virtual int contact() const { return -1; }
  virtual int rows() const = 0;
  virtual void bounds(Eigen::Ref<Eigen::VectorXd> lower,
                      Eigen::Ref<Eigen::VectorXd> upper) const = 0;
  // Appends the columns of x that row r may depend on (a superset of its nonzeros).
  virtual void row_columns(int r, std::vector<int>* columns) const = 0;
  virtual void evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const = 0;
  // Dense rows() x n, zeroed by the caller.
  virtual void jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const = 0;
  // H += sum_r y[r] d2 g_r / dx2 over x = [q | lambda] (n x n, both triangles), y: this block's
  // multipliers (hessian_terms.h has the pieces).
  virtual void add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                           Eigen::Ref<Eigen::MatrixXd> H) const = 0;

 private:
  std::string family_;
};

// Columns of x that can move a link of an entity: the floating root (7) and the dofs of the
// movable joints between the root and the link.
void append_link_columns(const System& system, int entity, int link, std::vector<int>* columns);
void append_entity_columns(const System& system, int entity, std::vector<int>* columns);
void append_force_columns(const NlpLayout& layout, int task, std::vector<int>* columns);
void sort_unique(std::vector<int>* columns);
// Columns every loaded contact touching `entity` brings in: what moves its s1, its s2 (the cone
// generators turn with s2's link) and its force coefficients.
void append_loaded_contact_columns(const NlpState& state, int entity, std::vector<int>* columns);

}  // namespace stanceplan
