#include <algorithm>
#include "planner/solver/hessian_terms.h"

#include "planner/contact/polygon.h"
#include "planner/solver/blocks/blocks.h"

namespace stanceplan {

PolygonBlock::PolygonBlock(const NlpState& state, int task, const std::vector<int>* only)
    : ConstraintBlock("polygon"), task_(task) {
  const ContactConstants& c = state.constants[task];
  const int vertices1 = static_cast<int>(c.v1_L.size());
  const auto& poly = c.v2_S;
  const int n = static_cast<int>(poly.size());
  for (int e = 0; e < n; ++e) {
    const Eigen::Vector2d inward = inward_normal(poly[e], poly[(e + 1) % n]);
    edge_normals_.push_back(inward);
    edge_offsets_.push_back(inward.dot(poly[e]));
  }
  for (int j = 0; j < vertices1; ++j)
    for (int e = 0; e < n; ++e)
      if (!only || std::find(only->begin(), only->end(), j * n + e) != only->end())
        rows_.push_back({j, e});
  append_link_columns(state.scene.system, c.e1, c.l1, &columns_);
  append_link_columns(state.scene.system, c.e2, c.l2, &columns_);
  sort_unique(&columns_);
}

void PolygonBlock::bounds(Eigen::Ref<Eigen::VectorXd> lower,
                          Eigen::Ref<Eigen::VectorXd> upper) const {
  lower.setZero();
  upper.setConstant(1e19);
}

void PolygonBlock::row_columns(int, std::vector<int>* columns) const {
  columns->insert(columns->end(), columns_.begin(), columns_.end());
}

// Row (j, e): (p_j - O2) . (n_x x2 + n_y y2) - n_e . a_e >= 0: vertex j of s1 on the inner side
// of edge e of s2.
void PolygonBlock::evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const {
  const ContactFrames& f = state.frames[task_];
  for (int r = 0; r < rows(); ++r) {
    const auto [j, e] = rows_[r];
    const Eigen::Vector3d w = edge_normals_[e].x() * f.x2 + edge_normals_[e].y() * f.y2;
    g[r] = (f.p[j] - f.O2).dot(w) - edge_offsets_[e];
  }
}

void PolygonBlock::jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const {
  state.ensure_jacobians();
  const ContactFrames& f = state.frames[task_];
  const ContactConstants& k = state.constants[task_];
  for (int r = 0; r < rows(); ++r) {
    const auto [j, e] = rows_[r];
    const double nx = edge_normals_[e].x(), ny = edge_normals_[e].y();
    const Eigen::Vector3d w = nx * f.x2 + ny * f.y2;
    const Eigen::Vector3d d = f.p[j] - f.O2;
    state.add_entity_term(k.e1, f.J_p[j], w, J.row(r));
    state.add_entity_term(k.e2, f.J_O2, -w, J.row(r));
    state.add_entity_term(k.e2, f.J_x2, nx * d, J.row(r));
    state.add_entity_term(k.e2, f.J_y2, ny * d, J.row(r));
  }
}

// Per vertex j the rows sum to (p_j - O2) . (a_x x2 + a_y y2), a = sum_e y_je n_e (a vertex's
// rows are consecutive).
void PolygonBlock::add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                               Eigen::Ref<Eigen::MatrixXd> H) const {
  state.ensure_jacobians();
  const ContactFrames& f = state.frames[task_];
  auto J_b = state.hessian_scratch[0].leftCols(f.J_x2.cols());
  for (int r = 0; r < rows();) {
    const int j = rows_[r].vertex;
    Eigen::Vector2d a = Eigen::Vector2d::Zero();
    for (; r < rows() && rows_[r].vertex == j; ++r) a += y[r] * edge_normals_[rows_[r].edge];
    if (a.isZero()) continue;
    const Eigen::Vector3d b = a.x() * f.x2 + a.y() * f.y2;
    J_b = a.x() * f.J_x2 + a.y() * f.J_y2;
    add_offset_dot_curvature(state, task_, f.p[j], f.J_p[j], b, J_b, 1.0, H);
  }
}

}  // namespace stanceplan
