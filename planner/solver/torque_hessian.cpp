#include "planner/solver/torque_hessian.h"

#include "planner/model/kinematics.h"
#include "planner/model/kinematics_hessian.h"
#include "planner/solver/hessian_terms.h"

namespace stanceplan {
namespace {

bool is_rotational(JointType type) {
  return type == JointType::Revolute || type == JointType::Continuous;
}

// Omega = sum over the revolute joints above `link` of m_j w[dof_j] a_j (the link's angular
// velocity under w) and J_Omega = dOmega/dq: a joint i above j turns a_j by a_i x a_j, the root by
// dR/dphi R^T.
Eigen::Vector3d angular_velocity_jacobian(const Entity& entity, const ModelData& data, int link,
                                          const Eigen::Ref<const Eigen::VectorXd>& w,
                                          Eigen::Ref<Eigen::MatrixXd> J) {
  const Model& model = *entity.model;
  J.setZero();
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  const int first_dof = entity.first_dof();
  // Walking up from the link, omega holds the rotation rates of the joints below the current one.
  for (int l = link; l > 0; l = model.links[l].parent_link) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    if (!joint.movable() || !is_rotational(joint.type)) continue;
    const Eigen::Vector3d& a = data.axis_W[j];
    J.col(first_dof + joint.dof) += joint.multiplier * a.cross(omega);
    omega += joint.multiplier * w[joint.dof] * a;
  }
  if (entity.floating())
    for (int i = 0; i < 4; ++i)
      J.col(Entity::kBaseQuaternion + i) = data.dR_WB_dquat[i] * (data.R_WB.transpose() * omega);
  return omega;
}

// H += d2(Omega . c)/dq2 with c held: Omega = sum_j m_j w_j a_j, each axis a_j a vector fixed to
// its joint's child link.
void add_angular_velocity_curvature(const Entity& entity, const ModelData& data, int link,
                                    const Eigen::Ref<const Eigen::VectorXd>& w,
                                    const Eigen::Vector3d& c, Eigen::Ref<Eigen::MatrixXd> H) {
  const Model& model = *entity.model;
  for (int l = link; l > 0; l = model.links[l].parent_link) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    const double scale = joint.multiplier * w[joint.dof];
    if (joint.movable() && is_rotational(joint.type) && scale != 0.0)
      add_vector_hessian(entity, data, l, data.axis_W[j], c, scale, H);
  }
}

// A point contact's couple (E18 with the couple of E17): its load F = sign f acts at p + a,
// a = -r z2 turning with l2, which is F at the centre p (add_load) plus the couple a x F. Weighted
// by w its torques are -Omega . (a x F) = a^T [Omega]x F, Omega the chain's angular velocity under
// w: a trilinear product (Omega on q_e, a on q_e2, F on lambda and q_e2) whose Hessian is each
// factor's curvature contracted with the other two plus the products of first derivatives.
void add_couple_load(NlpState& state, int e, int link, int task, int vertex, double sign,
                     Eigen::Ref<Eigen::MatrixXd> H) {
  const System& system = state.scene.system;
  const Entity& entity = system.entity(e);
  const ContactConstants& k = state.constants[task];
  const ContactFrames& fr = state.frames[task];
  const Eigen::Vector3d a = -k.radius * fr.z2;
  const Eigen::Vector3d F = sign * fr.f[vertex];
  const int nq = entity.nq(), offset = system.offset(e);
  auto J_omega = state.hessian_scratch[1].leftCols(nq);
  const Eigen::Vector3d omega =
      angular_velocity_jacobian(entity, state.data[e], link, state.torque_weights[e], J_omega);
  // Omega's own curvature, a and F held.
  add_angular_velocity_curvature(entity, state.data[e], link, state.torque_weights[e], -a.cross(F),
                                 H.block(offset, offset, nq, nq));
  // a's and F's, Omega held: a^T M f with M = sign [Omega]x (J_a = -r J_z2).
  const Eigen::Matrix3d M = sign * cross_matrix(omega);
  add_vector_curvature(state, k.e2, k.l2, a, M * fr.f[vertex], H);
  add_force_curvature(state, task, vertex, M.transpose() * a, H);
  add_force_cross_curvature(state, k.e2, fr.J_z2, task, vertex, -k.radius * M, H);
  // Omega's first derivatives with a's (Omega^T [F]x a) and with F's (-Omega^T [a]x F).
  add_cross_curvature(state, e, J_omega, k.e2, fr.J_z2, -k.radius * cross_matrix(F), H);
  add_force_cross_curvature(state, e, J_omega, task, vertex, -sign * cross_matrix(a), H);
}

// One load: the point p (s1's vertex, moving with e1/l1) pushes with F = sign f_j on the chain of
// link `link` of entity e; its term is -F . v(q_e, p). When the chain is s1's own link, p is fixed
// to it (the point velocity of kinematics_hessian.h). Otherwise (the load on s2's entity) p moves
// with e1, not with the chain: v = Omega x p + v0(q_e), which is the velocity V of the point p*
// fixed to the chain where p is now, less Omega x (p* - p).
void add_load(NlpState& state, int e, int link, int task, int vertex, double sign,
              Eigen::Ref<Eigen::MatrixXd> H) {
  const System& system = state.scene.system;
  const Entity& entity = system.entity(e);
  const ModelData& data = state.data[e];
  const ContactConstants& k = state.constants[task];
  const ContactFrames& fr = state.frames[task];
  const Eigen::Vector3d& p = fr.p[vertex];
  const Eigen::Vector3d F = sign * fr.f[vertex];
  const Eigen::VectorXd& w = state.torque_weights[e];
  const int nq = entity.nq(), offset = system.offset(e);
  auto J_v = state.hessian_scratch[0].leftCols(nq);
  const Eigen::Vector3d v = point_velocity_jacobian(entity, data, link, p, w, J_v);
  add_point_velocity_hessian(entity, data, link, p, w, -F, 1.0, H.block(offset, offset, nq, nq));
  if (!(e == k.e1 && link == k.l1)) {
    auto J_omega = state.hessian_scratch[1].leftCols(nq);
    auto J_pstar = state.hessian_scratch[2].leftCols(nq);
    const Eigen::Vector3d omega = angular_velocity_jacobian(entity, data, link, w, J_omega);
    point_jacobian_world(entity, data, link, p, J_pstar);
    // -(-F) . (Omega x (p* - p)) at p* = p: its second derivatives over q_e.
    J_v.noalias() -= cross_matrix(omega) * J_pstar;
    add_point_curvature(state, e, link, p, F.cross(omega), H);
    add_cross_curvature(state, e, J_omega, e, J_pstar, cross_matrix(-F), H);
    // -F . (Omega x p) with p moving with e1: p's curvature, and Omega^T [F]x p across entities.
    add_point_curvature(state, k.e1, k.l1, p, -F.cross(omega), H);
    add_cross_curvature(state, e, J_omega, k.e1, fr.J_p[vertex], cross_matrix(F), H);
    const int n1 = static_cast<int>(fr.J_p[vertex].cols());
    auto J_vp = state.hessian_scratch[3].leftCols(n1);  // dv/dq_e1 = [Omega]x J_p
    J_vp.noalias() = cross_matrix(omega) * fr.J_p[vertex];
    add_force_cross_curvature(state, k.e1, J_vp, task, vertex, -sign * Eigen::Matrix3d::Identity(),
                              H);
  }
  // F's curvature contracted with -v, and the products of F's and v's first derivatives.
  add_force_curvature(state, task, vertex, -sign * v, H);
  add_force_cross_curvature(state, e, J_v, task, vertex, -sign * Eigen::Matrix3d::Identity(), H);
  if (k.radius > 0.0) add_couple_load(state, e, link, task, vertex, sign, H);
}

}  // namespace

void add_weighted_torque_hessian(NlpState& state, Eigen::Ref<Eigen::MatrixXd> H) {
  state.ensure_jacobians();
  const System& system = state.scene.system;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    if (entity.model->num_dofs() == 0 || state.torque_weights[e].isZero()) continue;
    const int offset = system.offset(e), nq = entity.nq();
    // Gravity: -M g . v_C(w).
    add_com_velocity_hessian(entity, state.data[e], state.torque_weights[e],
                             -entity.model->total_mass * state.scene.gravity, 1.0,
                             H.block(offset, offset, nq, nq));
  }
  for (size_t t = 0; t < state.frames.size(); ++t) {
    if (state.layout.force_block_of_task[t] < 0) continue;
    const ContactConstants& c = state.constants[t];
    for (size_t j = 0; j < state.frames[t].p.size(); ++j) {
      if (system.entity(c.e1).model->num_dofs() > 0 && !state.torque_weights[c.e1].isZero())
        add_load(state, c.e1, c.l1, int(t), int(j), 1.0, H);
      if (system.entity(c.e2).model->num_dofs() > 0 && !state.torque_weights[c.e2].isZero())
        add_load(state, c.e2, c.l2, int(t), int(j), -1.0, H);
    }
  }
}

}  // namespace stanceplan
