#include "planner/model/kinematics_hessian.h"

#include <array>

#include "planner/model/kinematics.h"
#include "planner/model/quaternion.h"

// Notation (world frame throughout). A movable joint j has the column col_j = first_dof + dof_j of
// q, the multiplier m_j (mimic), the axis a_j and origin o_j. A_j is its rotation generator: a_j
// for a revolute joint, 0 for a prismatic one (a translation turns nothing). Joint values are
// m_j q[col_j] + offset, so a derivative with respect to q[col_j] is m_j times the one with
// respect to the joint value, summed over the joints sharing the column.
//
// The one rule behind every second derivative: turning joint i rotates everything below it
// rigidly, so any world quantity X carried by the links below i (a point's rate, an axis, a
// subtree's moment) changes by dX/dtheta_i = A_i x X. The floating root turns everything:
// dX/dphi_a = M_a X with M_a = dR/dphi_a R^T, and d2/dphi_a dphi_b = (d2R/dphi_a dphi_b) R^T.
// Cross products obey the product rule under a rotation, which gives the third derivatives
// d3p/dtheta_i dtheta_j dtheta_k = A_i x (A_j x t_k) for i above j above k on one chain.

namespace stanceplan {
namespace {

// Large enough for every model we load (TALOS: 60 links); larger ones take the per-link path.
constexpr int kMaxLinks = 256;

bool rotational(JointType type) {
  return type == JointType::Revolute || type == JointType::Continuous;
}

struct JointTerm {
  int col = 0;
  double multiplier = 1.0;
  bool rotates = false;
  Eigen::Vector3d A = Eigen::Vector3d::Zero();  // rotation generator, 0 for prismatic
  const Eigen::Vector3d* axis = nullptr;
  const Eigen::Vector3d* origin = nullptr;
};

JointTerm joint_term(const Entity& entity, const ModelData& data, int j) {
  const Joint& joint = entity.model->joints[j];
  JointTerm t;
  t.col = entity.first_dof() + joint.dof;
  t.multiplier = joint.multiplier;
  t.rotates = rotational(joint.type);
  if (t.rotates) t.A = data.axis_W[j];
  t.axis = &data.axis_W[j];
  t.origin = &data.origin_W[j];
  return t;
}

// dp/dtheta_j for the point at p (E30-E31): a x (p - o) or a.
Eigen::Vector3d point_rate(const JointTerm& t, const Eigen::Vector3d& p_W) {
  return t.rotates ? Eigen::Vector3d(t.A.cross(p_W - *t.origin)) : *t.axis;
}

// The movable joint above `link` nearest to it, as its child link; 0 when none is left.
int next_movable(const Model& model, int link) {
  while (link > 0 && !model.joints[model.links[link].parent_joint].movable())
    link = model.links[link].parent_link;
  return link;
}

// A mixed entry of two different joints (or a joint and a root coordinate): both triangles.
void add_pair(Eigen::Ref<Eigen::MatrixXd>& H, int r, int s, double value) {
  H(r, s) += value;
  H(s, r) += value;
}

// Root weights c_a with c . (M_a X) = c_a . X for every world vector X: c_a = R dR_a^T c.
std::array<Eigen::Vector3d, 4> root_turn_weights(const ModelData& data,
                                                 const Eigen::Vector3d& c_W) {
  std::array<Eigen::Vector3d, 4> c;
  for (int a = 0; a < 4; ++a) c[a] = data.R_WB * (data.dR_WB_dquat[a].transpose() * c_W);
  return c;
}

// phi-phi block for a quantity R(phi) x_B fixed in the root frame, x_B = R^T x_W.
void add_root_quaternion_block(const ModelData& data, const Eigen::Vector3d& x_W,
                               const Eigen::Vector3d& c_W, double scale,
                               Eigen::Ref<Eigen::MatrixXd>& H) {
  const Eigen::Vector3d x_B = data.R_WB.transpose() * x_W;
  H.block<4, 4>(Entity::kBaseQuaternion, Entity::kBaseQuaternion) +=
      scale * rotation_bilinear_hessian(data.quaternion_WB, c_W, x_B);
}

// The second derivatives of a quantity whose rate under joint j (child link lj) is X: joint j
// itself and every joint above it turn X (dX/dtheta_i = A_i x X, c . (A_i x X) = A_i . (X x c)),
// and so does the root. `weight` = scale * m_j.
void add_turns_of_rate(const Entity& entity, const ModelData& data, int lj, int col_j,
                       double weight, const Eigen::Vector3d& X, const Eigen::Vector3d& c_W,
                       const std::array<Eigen::Vector3d, 4>& c_root,
                       Eigen::Ref<Eigen::MatrixXd>& H) {
  const Model& model = *entity.model;
  if (entity.floating())
    for (int a = 0; a < 4; ++a)
      add_pair(H, Entity::kBaseQuaternion + a, col_j, weight * c_root[a].dot(X));
  const Eigen::Vector3d y = weight * X.cross(c_W);
  for (int li = next_movable(model, lj); li > 0;
       li = next_movable(model, model.links[li].parent_link)) {
    const int i = model.links[li].parent_joint;
    const Joint& joint = model.joints[i];
    if (!rotational(joint.type)) continue;
    const double value = joint.multiplier * data.axis_W[i].dot(y);
    if (li == lj)
      H(col_j, col_j) += value;
    else
      add_pair(H, entity.first_dof() + joint.dof, col_j, value);
  }
}

// Angular rate of the joints on the chain from `link` to the root under w: sum of m_j w_j A_j.
Eigen::Vector3d chain_angular_rate(const Entity& entity, const ModelData& data, int link,
                                   const Eigen::Ref<const Eigen::VectorXd>& w) {
  const Model& model = *entity.model;
  Eigen::Vector3d omega = Eigen::Vector3d::Zero();
  for (int l = next_movable(model, link); l > 0;
       l = next_movable(model, model.links[l].parent_link)) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    if (rotational(joint.type)) omega += joint.multiplier * w[joint.dof] * data.axis_W[j];
  }
  return omega;
}

// Walks the chain from the point up, calling f(lj, term, t_j, omega_above_j, g_j) for every
// movable joint j, where t_j = dp/dtheta_j, omega_above_j the angular rate of the joints strictly
// above j and g_j = dv/dtheta_j the rate of the point's velocity v under joint j:
//   g_j = sum_k m_k w_k d2p/dtheta_j dtheta_k = omega_above_j x t_j + A_j x (velocity of the
//   point from j and the joints below it).
template <class F>
void walk_point_velocity(const Entity& entity, const ModelData& data, int link,
                         const Eigen::Vector3d& p_W, const Eigen::Ref<const Eigen::VectorXd>& w,
                         const Eigen::Vector3d& omega_total, F&& f) {
  const Model& model = *entity.model;
  Eigen::Vector3d v_below = Eigen::Vector3d::Zero();      // from j and the joints below it
  Eigen::Vector3d omega_below = Eigen::Vector3d::Zero();  // likewise
  for (int lj = next_movable(model, link); lj > 0;
       lj = next_movable(model, model.links[lj].parent_link)) {
    const int j = model.links[lj].parent_joint;
    const JointTerm term = joint_term(entity, data, j);
    const double rate = term.multiplier * w[model.joints[j].dof];
    const Eigen::Vector3d t = point_rate(term, p_W);
    v_below += rate * t;
    omega_below += rate * term.A;
    const Eigen::Vector3d omega_above = omega_total - omega_below;
    f(lj, term, t, omega_above, Eigen::Vector3d(omega_above.cross(t) + term.A.cross(v_below)));
  }
}

// The velocity Hessian's joint-joint entry for the pair (i above-or-at j). It is the rate along w
// of the position Hessian's entry c . (A_i x X_j), X_j the rate of the moving thing under j (t_j,
// or the subtree's T_j): the axis turns at Omega_i x A_i (Omega_i: the angular rate of the joints
// strictly above i) and X_j changes at G_j, so
//   d2(c.v)/dtheta_i dtheta_j = c . [(Omega_i x A_i) x X_j + A_i x G_j]
// (the third derivatives summed with w; Jacobi's identity folds the joints above i, between i
// and j and at or below j into these two terms). With Xc_j = X_j x c and Gc_j = G_j x c:
double velocity_pair(const Eigen::Vector3d& A_i, const Eigen::Vector3d& omega_i,
                     const Eigen::Vector3d& Xc_j, const Eigen::Vector3d& Gc_j) {
  return omega_i.cross(A_i).dot(Xc_j) + A_i.dot(Gc_j);
}

void add_point_velocity_jacobian(const Entity& entity, const ModelData& data, int link,
                                 const Eigen::Vector3d& p_W,
                                 const Eigen::Ref<const Eigen::VectorXd>& w, double weight,
                                 Eigen::Vector3d* v, Eigen::Ref<Eigen::MatrixXd> J_v) {
  const Eigen::Vector3d omega = chain_angular_rate(entity, data, link, w);
  Eigen::Vector3d v_point = Eigen::Vector3d::Zero();
  walk_point_velocity(entity, data, link, p_W, w, omega,
                      [&](int, const JointTerm& term, const Eigen::Vector3d& t,
                          const Eigen::Vector3d&, const Eigen::Vector3d& g) {
                        v_point += term.multiplier * w[term.col - entity.first_dof()] * t;
                        J_v.col(term.col) += weight * term.multiplier * g;
                      });
  if (entity.floating())
    for (int a = 0; a < 4; ++a)
      J_v.col(Entity::kBaseQuaternion + a) +=
          weight * (data.dR_WB_dquat[a] * (data.R_WB.transpose() * v_point));
  *v += weight * v_point;
}

// Per-link fallback for models larger than kMaxLinks: the centre of mass's velocity is the
// mass-weighted sum of the link centres' velocities.
Eigen::Vector3d com_velocity_jacobian_per_link(const Entity& entity, const ModelData& data,
                                               const Eigen::Ref<const Eigen::VectorXd>& w,
                                               Eigen::Ref<Eigen::MatrixXd> J_v) {
  const Model& model = *entity.model;
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  for (int l = 0; l < model.num_links(); ++l) {
    const Inertial& inertial = model.links[l].inertial;
    if (inertial.mass <= 0.0) continue;
    add_point_velocity_jacobian(entity, data, l, data.T_WL[l] * inertial.p_LC, w,
                                inertial.mass / model.total_mass, &v, J_v);
  }
  return v;
}

// Subtree sums for the centre of mass's velocity, per link l with parent joint j:
//   T[l] = dC/dtheta_j (per unit joint value),
//   omega_path[l] = angular rate of the joints from the root down to j inclusive,
//   U[l] = sum of m_k w_k T_k over the joints k at or below j (the subtree's share of v_C),
//   G[l] = dv_C/dtheta_j = A_j x U[l] + omega_above_j x T[l].
struct ComVelocityTerms {
  std::array<Eigen::Vector3d, kMaxLinks> T, omega_path, U, G;
};

void com_velocity_terms(const Entity& entity, const ModelData& data,
                        const Eigen::Ref<const Eigen::VectorXd>& w, ComVelocityTerms* s) {
  const Model& model = *entity.model;
  const double inv_mass = 1.0 / model.total_mass;
  s->T[0].setZero();
  s->omega_path[0].setZero();
  s->U[0].setZero();
  for (int l = 1; l < model.num_links(); ++l) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    const Eigen::Vector3d& omega_parent = s->omega_path[model.links[l].parent_link];
    if (!joint.movable()) {
      s->T[l].setZero();
      s->omega_path[l] = omega_parent;
      s->U[l].setZero();
      continue;
    }
    const double rate = joint.multiplier * w[joint.dof];
    const double m = model.subtree_mass[l];
    const Eigen::Vector3d& a = data.axis_W[j];
    // As center_of_mass_jacobian: j turns the subtree's moment about its origin, or slides it.
    if (rotational(joint.type)) {
      s->T[l] = inv_mass * a.cross(data.subtree_moment_W[l] - m * data.origin_W[j]);
      s->omega_path[l] = omega_parent + rate * a;
    } else {
      s->T[l] = inv_mass * m * a;
      s->omega_path[l] = omega_parent;
    }
    s->U[l] = rate * s->T[l];
  }
  for (int l = model.num_links() - 1; l > 0; --l) s->U[model.links[l].parent_link] += s->U[l];
  for (int l = 1; l < model.num_links(); ++l) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    s->G[l].setZero();
    if (!joint.movable()) continue;
    const Eigen::Vector3d& omega_above = s->omega_path[model.links[l].parent_link];
    s->G[l] = omega_above.cross(s->T[l]);
    if (rotational(joint.type)) s->G[l] += data.axis_W[j].cross(s->U[l]);
  }
}

}  // namespace

void add_point_hessian(const Entity& entity, const ModelData& data, int link,
                       const Eigen::Vector3d& p_W, const Eigen::Vector3d& c_W, double scale,
                       Eigen::Ref<Eigen::MatrixXd> H) {
  // p = p_WB + R(phi) p_B(theta): nothing second-order in p_WB; phi-phi from d2R; phi-theta and
  // theta-theta: the joints above-or-at j and the root turn t_j.
  const Model& model = *entity.model;
  std::array<Eigen::Vector3d, 4> c_root;
  if (entity.floating()) {
    c_root = root_turn_weights(data, c_W);
    add_root_quaternion_block(data, p_W - data.p_WB, c_W, scale, H);
  }
  for (int lj = next_movable(model, link); lj > 0;
       lj = next_movable(model, model.links[lj].parent_link)) {
    const JointTerm term = joint_term(entity, data, model.links[lj].parent_joint);
    add_turns_of_rate(entity, data, lj, term.col, scale * term.multiplier, point_rate(term, p_W),
                      c_W, c_root, H);
  }
}

void add_vector_hessian(const Entity& entity, const ModelData& data, int link,
                        const Eigen::Vector3d& v_W, const Eigen::Vector3d& c_W, double scale,
                        Eigen::Ref<Eigen::MatrixXd> H) {
  // dv/dtheta_j = A_j x v (E32-E33), turned in turn by the joints above-or-at j and the root.
  const Model& model = *entity.model;
  std::array<Eigen::Vector3d, 4> c_root;
  if (entity.floating()) {
    c_root = root_turn_weights(data, c_W);
    add_root_quaternion_block(data, v_W, c_W, scale, H);
  }
  for (int lj = next_movable(model, link); lj > 0;
       lj = next_movable(model, model.links[lj].parent_link)) {
    const JointTerm term = joint_term(entity, data, model.links[lj].parent_joint);
    if (!term.rotates) continue;
    add_turns_of_rate(entity, data, lj, term.col, scale * term.multiplier, term.A.cross(v_W), c_W,
                      c_root, H);
  }
}

Eigen::Vector3d point_velocity_jacobian(const Entity& entity, const ModelData& data, int link,
                                        const Eigen::Vector3d& p_W,
                                        const Eigen::Ref<const Eigen::VectorXd>& w,
                                        Eigen::Ref<Eigen::MatrixXd> J_v) {
  // v = sum_j m_j w_j t_j; dv/dtheta_j = g_j (walk_point_velocity); the root turns v:
  // dv/dphi_a = M_a v; v does not depend on p_WB.
  J_v.setZero();
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  add_point_velocity_jacobian(entity, data, link, p_W, w, 1.0, &v, J_v);
  return v;
}

void add_point_velocity_hessian(const Entity& entity, const ModelData& data, int link,
                                const Eigen::Vector3d& p_W,
                                const Eigen::Ref<const Eigen::VectorXd>& w,
                                const Eigen::Vector3d& c_W, double scale,
                                Eigen::Ref<Eigen::MatrixXd> H) {
  const Model& model = *entity.model;
  const Eigen::Vector3d omega = chain_angular_rate(entity, data, link, w);
  std::array<Eigen::Vector3d, 4> c_root;
  if (entity.floating()) c_root = root_turn_weights(data, c_W);
  Eigen::Vector3d v = Eigen::Vector3d::Zero();
  walk_point_velocity(
      entity, data, link, p_W, w, omega,
      [&](int lj, const JointTerm& term_j, const Eigen::Vector3d& t_j,
          const Eigen::Vector3d& omega_above_j, const Eigen::Vector3d& g_j) {
        v += term_j.multiplier * w[term_j.col - entity.first_dof()] * t_j;
        const double weight = scale * term_j.multiplier;
        // phi-theta: the root turns dv/dtheta_j.
        if (entity.floating())
          for (int a = 0; a < 4; ++a)
            add_pair(H, Entity::kBaseQuaternion + a, term_j.col, weight * c_root[a].dot(g_j));
        // theta-theta, i above-or-at j; omega_i (strictly above i) found by removing the joints
        // from i down to j's parent as the walk climbs.
        const Eigen::Vector3d tc_j = t_j.cross(c_W), gc_j = g_j.cross(c_W);
        Eigen::Vector3d omega_i = omega_above_j;
        for (int li = lj; li > 0; li = next_movable(model, model.links[li].parent_link)) {
          const JointTerm term_i = joint_term(entity, data, model.links[li].parent_joint);
          if (li != lj)
            omega_i -= term_i.multiplier * w[term_i.col - entity.first_dof()] * term_i.A;
          if (!term_i.rotates) continue;
          const double value =
              weight * term_i.multiplier * velocity_pair(term_i.A, omega_i, tc_j, gc_j);
          if (li == lj)
            H(term_j.col, term_j.col) += value;
          else
            add_pair(H, term_i.col, term_j.col, value);
        }
      });
  if (entity.floating()) add_root_quaternion_block(data, v, c_W, scale, H);
}

void add_com_hessian(const Entity& entity, const ModelData& data, const Eigen::Vector3d& c_W,
                     double scale, Eigen::Ref<Eigen::MatrixXd> H) {
  // C = S_0 / M. dC/dtheta_j = T_j = a_j x (S_j - M_j o_j) / M (or M_j a_j / M): the rate of the
  // subtree below j, turned by the joints above-or-at j and by the root; joints on different
  // branches do not couple (no link lies below both).
  const Model& model = *entity.model;
  if (model.total_mass <= 0.0) return;  // C = p_WB then: linear in q
  const double inv_mass = 1.0 / model.total_mass;
  std::array<Eigen::Vector3d, 4> c_root;
  if (entity.floating()) {
    c_root = root_turn_weights(data, c_W);
    add_root_quaternion_block(data, center_of_mass(entity, data) - data.p_WB, c_W, scale, H);
  }
  for (int l = 1; l < model.num_links(); ++l) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    if (!joint.movable()) continue;
    const double m = model.subtree_mass[l];
    const Eigen::Vector3d& a = data.axis_W[j];
    const Eigen::Vector3d T =
        rotational(joint.type)
            ? Eigen::Vector3d(inv_mass * a.cross(data.subtree_moment_W[l] - m * data.origin_W[j]))
            : Eigen::Vector3d(inv_mass * m * a);
    add_turns_of_rate(entity, data, l, entity.first_dof() + joint.dof, scale * joint.multiplier, T,
                      c_W, c_root, H);
  }
}

Eigen::Vector3d com_velocity_jacobian(const Entity& entity, const ModelData& data,
                                      const Eigen::Ref<const Eigen::VectorXd>& w,
                                      Eigen::Ref<Eigen::MatrixXd> J_v) {
  const Model& model = *entity.model;
  J_v.setZero();
  if (model.total_mass <= 0.0) return Eigen::Vector3d::Zero();
  if (model.num_links() > kMaxLinks) return com_velocity_jacobian_per_link(entity, data, w, J_v);
  ComVelocityTerms s;
  com_velocity_terms(entity, data, w, &s);
  for (int l = 1; l < model.num_links(); ++l) {
    const Joint& joint = model.joints[model.links[l].parent_joint];
    if (joint.movable()) J_v.col(entity.first_dof() + joint.dof) += joint.multiplier * s.G[l];
  }
  const Eigen::Vector3d v_C = s.U[0];
  if (entity.floating())
    for (int a = 0; a < 4; ++a)
      J_v.col(Entity::kBaseQuaternion + a) = data.dR_WB_dquat[a] * (data.R_WB.transpose() * v_C);
  return v_C;
}

void add_com_velocity_hessian(const Entity& entity, const ModelData& data,
                              const Eigen::Ref<const Eigen::VectorXd>& w,
                              const Eigen::Vector3d& c_W, double scale,
                              Eigen::Ref<Eigen::MatrixXd> H) {
  // Same pairs as the point's velocity (velocity_pair) with the subtree's T_j, G_j in place of
  // t_j, g_j: the joints at or below j now span j's whole subtree (U), not one chain.
  const Model& model = *entity.model;
  if (model.total_mass <= 0.0) return;
  if (model.num_links() > kMaxLinks) {
    for (int l = 0; l < model.num_links(); ++l) {
      const Inertial& inertial = model.links[l].inertial;
      if (inertial.mass > 0.0)
        add_point_velocity_hessian(entity, data, l, data.T_WL[l] * inertial.p_LC, w, c_W,
                                   scale * inertial.mass / model.total_mass, H);
    }
    return;
  }
  ComVelocityTerms s;
  com_velocity_terms(entity, data, w, &s);
  std::array<Eigen::Vector3d, 4> c_root;
  if (entity.floating()) {
    c_root = root_turn_weights(data, c_W);
    add_root_quaternion_block(data, s.U[0], c_W, scale, H);
  }
  for (int lj = 1; lj < model.num_links(); ++lj) {
    const Joint& joint_j = model.joints[model.links[lj].parent_joint];
    if (!joint_j.movable()) continue;
    const int col_j = entity.first_dof() + joint_j.dof;
    const double weight = scale * joint_j.multiplier;
    if (entity.floating())
      for (int a = 0; a < 4; ++a)
        add_pair(H, Entity::kBaseQuaternion + a, col_j, weight * c_root[a].dot(s.G[lj]));
    const Eigen::Vector3d Tc_j = s.T[lj].cross(c_W), Gc_j = s.G[lj].cross(c_W);
    for (int li = lj; li > 0; li = next_movable(model, model.links[li].parent_link)) {
      const int i = model.links[li].parent_joint;
      const Joint& joint_i = model.joints[i];
      if (!rotational(joint_i.type)) continue;
      const Eigen::Vector3d& omega_i = s.omega_path[model.links[li].parent_link];
      const double value =
          weight * joint_i.multiplier * velocity_pair(data.axis_W[i], omega_i, Tc_j, Gc_j);
      if (li == lj)
        H(col_j, col_j) += value;
      else
        add_pair(H, entity.first_dof() + joint_i.dof, col_j, value);
    }
  }
}

}  // namespace stanceplan
