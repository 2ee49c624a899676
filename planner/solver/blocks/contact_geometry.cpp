#include <algorithm>
#include <cmath>
#include "planner/solver/hessian_terms.h"

#include "planner/solver/blocks/blocks.h"

namespace stanceplan {
namespace {
constexpr double kInf = 1e19;  // Ipopt's "no bound"
}

// A point contact (s1 a sphere of radius r centred at O1 = c, surface.h) has no orientation: E8,
// E12 and E13 do not apply. It keeps E9 as (c - O2) . z2 = r, the contact point c - r z2 on s2's
// plane, and for a fixed placement E10-E11, whose (x, y) are those of c and of the contact point
// alike. Its rows: E9 [, E10, E11].
int ContactGeometryBlock::row_e9() const {
  return point_ ? 0 : 2;
}
int ContactGeometryBlock::row_e10() const {
  return point_ ? 1 : 4;
}
int ContactGeometryBlock::row_e11() const {
  return point_ ? 2 : 5;
}

ContactGeometryBlock::ContactGeometryBlock(const NlpState& state, int task)
    : ConstraintBlock("contact_geometry"), task_(task) {
  const ContactTask& t = state.request.contacts[task];
  fixed_ = t.placement.has_value();
  if (fixed_) placement_ = *t.placement;
  const Surface& s1 = state.scene.surfaces.get(t.contact.s1);
  point_ = s1.is_point();
  radius_ = s1.radius;
  standoff_ = t.standoff;
  const ContactConstants& c = state.constants[task];
  append_link_columns(state.scene.system, c.e1, c.l1, &columns_);
  append_link_columns(state.scene.system, c.e2, c.l2, &columns_);
  sort_unique(&columns_);
}

void ContactGeometryBlock::bounds(Eigen::Ref<Eigen::VectorXd> lower,
                                  Eigen::Ref<Eigen::VectorXd> upper) const {
  lower.setZero();
  upper.setZero();
  if (point_) {
    lower[row_e9()] = upper[row_e9()] = radius_ + standoff_;  // E9: the centre r above the plane
  } else {
    lower[2] = upper[2] = standoff_;  // E9, held above the plane when the task says so
    lower[3] = -kInf;                 // z1 . z2 <= 0: the opposed branch of E8
  }
  if (!fixed_) return;
  lower[row_e10()] = upper[row_e10()] = placement_.x;
  lower[row_e11()] = upper[row_e11()] = placement_.y;
  if (point_) return;
  upper[7] = kInf;  // x1 . (cos x2 + sin y2) >= 0: the right branch of E12-E13
}

void ContactGeometryBlock::row_columns(int, std::vector<int>* columns) const {
  columns->insert(columns->end(), columns_.begin(), columns_.end());
}

void ContactGeometryBlock::evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const {
  const ContactFrames& f = state.frames[task_];
  const Eigen::Vector3d d = f.O1 - f.O2;
  if (!point_) {
    g[0] = f.z1.dot(f.x2);  // E8: z1 = -z2, as two orthogonality conditions
    g[1] = f.z1.dot(f.y2);
    g[3] = f.z1.dot(f.z2);
  }
  g[row_e9()] = d.dot(f.z2);  // E9: s1's origin on s2's plane (a point's centre r above it)
  if (!fixed_) return;
  g[row_e10()] = d.dot(f.x2);  // E10-E11: placement
  g[row_e11()] = d.dot(f.y2);
  if (point_) return;
  const double theta = state.request.contacts[task_].placement->theta;  // see jacobian()
  const double c = std::cos(theta), s = std::sin(theta);
  g[6] = c * f.x1.dot(f.y2) - s * f.x1.dot(f.x2);  // E12-E13: sin(theta_1 - theta_c) = 0
  g[7] = c * f.x1.dot(f.x2) + s * f.x1.dot(f.y2);
}

void ContactGeometryBlock::jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const {
  state.ensure_jacobians();
  const ContactFrames& f = state.frames[task_];
  const ContactConstants& k = state.constants[task_];
  const Eigen::Vector3d d = f.O1 - f.O2;
  // d(a . b) = b^T da + a^T db, each on the entity the vector moves with.
  auto dot_s1_s2 = [&](int row, const Eigen::MatrixXd& Ja, const Eigen::Vector3d& a,
                       const Eigen::MatrixXd& Jb, const Eigen::Vector3d& b, double w) {
    state.add_entity_term(k.e1, Ja, w * b, J.row(row));
    state.add_entity_term(k.e2, Jb, w * a, J.row(row));
  };
  auto offset_dot = [&](int row, const Eigen::MatrixXd& Jb, const Eigen::Vector3d& b) {
    state.add_entity_term(k.e1, f.J_O1, b, J.row(row));
    state.add_entity_term(k.e2, f.J_O2, -b, J.row(row));
    state.add_entity_term(k.e2, Jb, d, J.row(row));
  };
  if (!point_) {
    dot_s1_s2(0, f.J_z1, f.z1, f.J_x2, f.x2, 1.0);
    dot_s1_s2(1, f.J_z1, f.z1, f.J_y2, f.y2, 1.0);
    dot_s1_s2(3, f.J_z1, f.z1, f.J_z2, f.z2, 1.0);
  }
  offset_dot(row_e9(), f.J_z2, f.z2);
  if (!fixed_) return;
  offset_dot(row_e10(), f.J_x2, f.x2);
  offset_dot(row_e11(), f.J_y2, f.y2);
  if (point_) return;
  // The angle of the state's request, not the one this block was made with: the Hessian's
  // structure is measured on a generic request (PostureNlp::generic_request), where an angle of
  // exactly 0 (s = 0) would otherwise hide the -s terms and make the cached structure depend on
  // which request came first (results then depended on the thread count).
  const double theta = state.request.contacts[task_].placement->theta;
  const double c = std::cos(theta), s = std::sin(theta);
  dot_s1_s2(6, f.J_x1, f.x1, f.J_y2, f.y2, c);
  dot_s1_s2(6, f.J_x1, f.x1, f.J_x2, f.x2, -s);
  dot_s1_s2(7, f.J_x1, f.x1, f.J_x2, f.x2, c);
  dot_s1_s2(7, f.J_x1, f.x1, f.J_y2, f.y2, s);
}

// The rows are dot products of s1's and s2's frame vectors: the weighted sum collapses into three
// of them, z1 . W, (O1 - O2) . B and x1 . V, with W, B and V combinations of s2's axes.
void ContactGeometryBlock::add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                                       Eigen::Ref<Eigen::MatrixXd> H) const {
  state.ensure_jacobians();
  const ContactFrames& f = state.frames[task_];
  const ContactConstants& k = state.constants[task_];
  const int n2 = static_cast<int>(f.J_x2.cols());
  auto J_W = state.hessian_scratch[0].leftCols(n2);
  auto J_B = state.hessian_scratch[1].leftCols(n2);
  if (!point_) {
    const Eigen::Vector3d W = y[0] * f.x2 + y[1] * f.y2 + y[3] * f.z2;
    J_W = y[0] * f.J_x2 + y[1] * f.J_y2 + y[3] * f.J_z2;
    add_vector_dot_curvature(state, k.e1, k.l1, f.z1, f.J_z1, k.e2, k.l2, W, J_W, 1.0, H);
  }
  Eigen::Vector3d B = y[row_e9()] * f.z2;
  J_B = y[row_e9()] * f.J_z2;
  if (fixed_) {
    B += y[row_e10()] * f.x2 + y[row_e11()] * f.y2;
    J_B += y[row_e10()] * f.J_x2 + y[row_e11()] * f.J_y2;
  }
  add_offset_dot_curvature(state, task_, f.O1, f.J_O1, B, J_B, 1.0, H);
  if (!fixed_ || point_) return;
  const double theta = state.request.contacts[task_].placement->theta;  // see jacobian()
  const double c = std::cos(theta), s = std::sin(theta);
  const double on_y2 = c * y[6] + s * y[7], on_x2 = -s * y[6] + c * y[7];
  const Eigen::Vector3d V = on_y2 * f.y2 + on_x2 * f.x2;
  J_W = on_y2 * f.J_y2 + on_x2 * f.J_x2;
  add_vector_dot_curvature(state, k.e1, k.l1, f.x1, f.J_x1, k.e2, k.l2, V, J_W, 1.0, H);
}

}  // namespace stanceplan
