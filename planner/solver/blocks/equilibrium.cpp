#include <algorithm>
#include "planner/solver/hessian_terms.h"

#include "planner/solver/blocks/blocks.h"

namespace stanceplan {
namespace {

// A point contact's force acts at c - r z2, r z2 below the sphere's centre c, which is its vertex
// p (surface.h): the moment of f is (p - r z2) x f, the vertex's plus the couple -r z2 x f. The
// offset -r z2 turns with s2's link. 0 for a polygon contact.
double point_radius(const NlpState& state, int task) {
  return state.constants[task].radius;
}

}  // namespace

EquilibriumBlock::EquilibriumBlock(const NlpState& state, int entity)
    : ConstraintBlock("equilibrium"), entity_(entity) {
  const System& system = state.scene.system;
  scale_ = 1.0 / (system.entity(entity).model->total_mass * state.scene.gravity.norm());
  append_entity_columns(system, entity, &columns_);
  for (int t = 0; t < static_cast<int>(state.constants.size()); ++t) {
    if (state.layout.force_block_of_task[t] < 0) continue;
    const ContactConstants& c = state.constants[t];
    if (c.e1 != entity && c.e2 != entity) continue;
    for (int j = 0; j < static_cast<int>(c.v1_L.size()); ++j) {
      // E16-E17 sign rule: +f as the smaller surface's entity, -f as the larger's.
      if (c.e1 == entity) received_.push_back({t, j, 1.0});
      if (c.e2 == entity) received_.push_back({t, j, -1.0});
    }
  }
  append_loaded_contact_columns(state, entity, &columns_);
  sort_unique(&columns_);
}

void EquilibriumBlock::bounds(Eigen::Ref<Eigen::VectorXd> lower,
                              Eigen::Ref<Eigen::VectorXd> upper) const {
  lower.setZero();
  upper.setZero();
}

void EquilibriumBlock::row_columns(int, std::vector<int>* columns) const {
  columns->insert(columns->end(), columns_.begin(), columns_.end());
}

void EquilibriumBlock::evaluate(NlpState& state, Eigen::Ref<Eigen::VectorXd> g) const {
  const double mass = state.scene.system.entity(entity_).model->total_mass;
  const Eigen::Vector3d weight = mass * state.scene.gravity;
  Eigen::Vector3d force = weight;                             // E16
  Eigen::Vector3d moment = state.com[entity_].cross(weight);  // E17, about the world origin
  for (const Received& r : received_) {
    const ContactFrames& f = state.frames[r.task];
    const Eigen::Vector3d p = f.p[r.vertex] - point_radius(state, r.task) * f.z2;
    force += r.sign * f.f[r.vertex];
    moment += r.sign * p.cross(f.f[r.vertex]);
  }
  g.head<3>() = scale_ * force;
  g.tail<3>() = scale_ * moment;
}

void EquilibriumBlock::jacobian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> J) const {
  state.ensure_jacobians();
  const double mass = state.scene.system.entity(entity_).model->total_mass;
  const Eigen::Vector3d weight = mass * state.scene.gravity;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
    // (C x mg)_i = C . (mg x e_i)
    state.add_entity_term(entity_, state.J_com[entity_], scale_ * weight.cross(e), J.row(3 + i));
    for (const Received& r : received_) {
      const ContactFrames& f = state.frames[r.task];
      const double w = r.sign * scale_;
      state.add_force_term(r.task, r.vertex, w * e, J.row(i));
      // (p x f)_i = p . (f x e_i) = f . (e_i x p)
      const int e1 = state.constants[r.task].e1, e2 = state.constants[r.task].e2;
      const double radius = point_radius(state, r.task);
      state.add_entity_term(e1, f.J_p[r.vertex], w * f.f[r.vertex].cross(e), J.row(3 + i));
      if (radius > 0.0)  // the point contact's offset -r z2 (E17 adapted)
        state.add_entity_term(e2, f.J_z2, -radius * w * f.f[r.vertex].cross(e), J.row(3 + i));
      const Eigen::Vector3d p = f.p[r.vertex] - radius * f.z2;
      state.add_force_term(r.task, r.vertex, w * e.cross(p), J.row(3 + i));
    }
  }
}

// y_f . (sum s f_j) + y_m . (sum s p_j x f_j + C x m g), all times 1 / (m |g|):
// y_m . (p x f) = p^T M f with M = -[y_m]x. A point contact's load point is p - r z2: its offset
// adds a^T M f with a = -r z2 on s2's link (its own curvature and its cross terms with f).
void EquilibriumBlock::add_hessian(NlpState& state, const Eigen::Ref<const Eigen::VectorXd>& y,
                                   Eigen::Ref<Eigen::MatrixXd> H) const {
  state.ensure_jacobians();
  const double mass = state.scene.system.entity(entity_).model->total_mass;
  const Eigen::Vector3d weight = mass * state.scene.gravity;
  const Eigen::Vector3d y_f = scale_ * y.head<3>(), y_m = scale_ * y.tail<3>();
  add_com_curvature(state, entity_, weight.cross(y_m), H);  // C . (m g x y_m)
  for (const Received& r : received_) {
    const ContactFrames& f = state.frames[r.task];
    const ContactConstants& k = state.constants[r.task];
    const double radius = point_radius(state, r.task);
    const Eigen::Vector3d& p = f.p[r.vertex];
    const Eigen::Matrix3d M = -r.sign * cross_matrix(y_m);
    add_force_curvature(state, r.task, r.vertex, r.sign * y_f + M.transpose() * (p - radius * f.z2),
                        H);
    add_point_curvature(state, k.e1, k.l1, p, M * f.f[r.vertex], H);
    add_force_cross_curvature(state, k.e1, f.J_p[r.vertex], r.task, r.vertex, M, H);
    if (radius > 0.0) {
      add_vector_curvature(state, k.e2, k.l2, -radius * f.z2, M * f.f[r.vertex], H);
      add_force_cross_curvature(state, k.e2, f.J_z2, r.task, r.vertex, -radius * M, H);
    }
  }
}

}  // namespace stanceplan
