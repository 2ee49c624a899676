#include "planner/solver/hessian_terms.h"

#include "planner/model/kinematics_hessian.h"

namespace stanceplan {
namespace {

// The block of H over one entity's configuration columns.
auto entity_block(const NlpState& state, int entity, Eigen::Ref<Eigen::MatrixXd> H) {
  const int offset = state.scene.system.offset(entity);
  const int nq = state.scene.system.entity(entity).nq();
  return H.block(offset, offset, nq, nq);
}

}  // namespace

Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v) {
  Eigen::Matrix3d m;
  m << 0.0, -v.z(), v.y(), v.z(), 0.0, -v.x(), -v.y(), v.x(), 0.0;
  return m;
}

void add_point_curvature(const NlpState& state, int entity, int link, const Eigen::Vector3d& p_W,
                         const Eigen::Vector3d& c, Eigen::Ref<Eigen::MatrixXd> H) {
  const Entity& e = state.scene.system.entity(entity);
  if (e.nq() == 0) return;
  add_point_hessian(e, state.data[entity], link, p_W, c, 1.0, entity_block(state, entity, H));
}

void add_vector_curvature(const NlpState& state, int entity, int link, const Eigen::Vector3d& v_W,
                          const Eigen::Vector3d& c, Eigen::Ref<Eigen::MatrixXd> H) {
  const Entity& e = state.scene.system.entity(entity);
  if (e.nq() == 0) return;
  add_vector_hessian(e, state.data[entity], link, v_W, c, 1.0, entity_block(state, entity, H));
}

void add_cross_curvature(const NlpState& state, int ea,
                         const Eigen::Ref<const Eigen::MatrixXd>& J_a, int eb,
                         const Eigen::Ref<const Eigen::MatrixXd>& J_b, const Eigen::Matrix3d& M,
                         Eigen::Ref<Eigen::MatrixXd> H) {
  const int na = static_cast<int>(J_a.cols()), nb = static_cast<int>(J_b.cols());
  if (na == 0 || nb == 0) return;
  const System& system = state.scene.system;
  const int oa = system.offset(ea), ob = system.offset(eb);
  // M J_b in a fixed-capacity buffer: no allocation for entities up to kMaxColumns columns.
  constexpr int kMaxColumns = 128;
  if (nb <= kMaxColumns) {
    Eigen::Matrix<double, 3, Eigen::Dynamic, Eigen::ColMajor, 3, kMaxColumns> MJ_b(3, nb);
    MJ_b.noalias() = M * J_b;
    H.block(oa, ob, na, nb).noalias() += J_a.transpose() * MJ_b;
    H.block(ob, oa, nb, na).noalias() += MJ_b.transpose() * J_a;
    return;
  }
  const Eigen::MatrixXd MJ_b = M * J_b;
  H.block(oa, ob, na, nb).noalias() += J_a.transpose() * MJ_b;
  H.block(ob, oa, nb, na).noalias() += MJ_b.transpose() * J_a;
}

void add_column_curvature(const NlpState& state, int column, int entity,
                          const Eigen::Ref<const Eigen::MatrixXd>& J, const Eigen::Vector3d& c,
                          Eigen::Ref<Eigen::MatrixXd> H) {
  const int nq = static_cast<int>(J.cols());
  if (nq == 0) return;
  const int offset = state.scene.system.offset(entity);
  H.row(column).segment(offset, nq).noalias() += c.transpose() * J;
  H.col(column).segment(offset, nq).noalias() += J.transpose() * c;
}

void add_force_curvature(const NlpState& state, int task, int vertex, const Eigen::Vector3d& c,
                         Eigen::Ref<Eigen::MatrixXd> H) {
  const ForceBlock& block = state.layout.forces[state.layout.force_block_of_task[task]];
  if (block.bilateral) return;  // f = lambda: linear, no curvature of its own
  const ContactConstants& k = state.constants[task];
  const ContactFrames& f = state.frames[task];
  const int first = block.first_column + vertex * block.per_vertex;
  for (int g = 0; g < block.per_vertex; ++g)
    add_column_curvature(state, first + g, k.e2, f.J_U[g], c, H);
  add_vector_curvature(state, k.e2, k.l2, f.f[vertex], c, H);
}

void add_force_cross_curvature(const NlpState& state, int ea,
                               const Eigen::Ref<const Eigen::MatrixXd>& J_a, int task, int vertex,
                               const Eigen::Matrix3d& M, Eigen::Ref<Eigen::MatrixXd> H) {
  const ForceBlock& block = state.layout.forces[state.layout.force_block_of_task[task]];
  const ContactFrames& f = state.frames[task];
  const int first = block.first_column + vertex * block.per_vertex;
  if (block.bilateral) {
    for (int i = 0; i < 3; ++i) add_column_curvature(state, first + i, ea, J_a, M.col(i), H);
    return;
  }
  for (int g = 0; g < block.per_vertex; ++g)
    add_column_curvature(state, first + g, ea, J_a, M * f.U[g], H);
  add_cross_curvature(state, ea, J_a, state.constants[task].e2, f.J_f[vertex], M, H);
}

void add_vector_dot_curvature(const NlpState& state, int ea, int la, const Eigen::Vector3d& a,
                              const Eigen::Ref<const Eigen::MatrixXd>& J_a, int eb, int lb,
                              const Eigen::Vector3d& b,
                              const Eigen::Ref<const Eigen::MatrixXd>& J_b, double scale,
                              Eigen::Ref<Eigen::MatrixXd> H) {
  if (scale == 0.0) return;
  add_vector_curvature(state, ea, la, a, scale * b, H);
  add_vector_curvature(state, eb, lb, b, scale * a, H);
  add_cross_curvature(state, ea, J_a, eb, J_b, scale * Eigen::Matrix3d::Identity(), H);
}

void add_offset_dot_curvature(const NlpState& state, int task, const Eigen::Vector3d& p1,
                              const Eigen::Ref<const Eigen::MatrixXd>& J_p1,
                              const Eigen::Vector3d& b,
                              const Eigen::Ref<const Eigen::MatrixXd>& J_b, double scale,
                              Eigen::Ref<Eigen::MatrixXd> H) {
  if (scale == 0.0) return;
  const ContactConstants& k = state.constants[task];
  const ContactFrames& f = state.frames[task];
  const Eigen::Matrix3d I = scale * Eigen::Matrix3d::Identity();
  add_point_curvature(state, k.e1, k.l1, p1, scale * b, H);
  add_point_curvature(state, k.e2, k.l2, f.O2, -scale * b, H);
  add_vector_curvature(state, k.e2, k.l2, b, scale * (p1 - f.O2), H);
  add_cross_curvature(state, k.e1, J_p1, k.e2, J_b, I, H);
  add_cross_curvature(state, k.e2, f.J_O2, k.e2, J_b, -I, H);
}

void add_com_curvature(const NlpState& state, int entity, const Eigen::Vector3d& c,
                       Eigen::Ref<Eigen::MatrixXd> H) {
  const Entity& e = state.scene.system.entity(entity);
  if (e.nq() == 0) return;
  add_com_hessian(e, state.data[entity], c, 1.0, entity_block(state, entity, H));
}

}  // namespace stanceplan
