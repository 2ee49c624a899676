#include "planner/solver/joint_torques.h"

namespace stanceplan {
namespace {

bool rotational(JointType type) {
  return type == JointType::Revolute || type == JointType::Continuous;
}

// Derivative of the joint quantity h(a, o) through the motion of a joint's axis a and origin o
// caused by every joint above it and by the floating root. dh_da, dh_do: partials of h.
void add_frame_motion(const Entity& entity, const ModelData& data, int above_link,
                      const Eigen::Vector3d& a, const Eigen::Vector3d& o,
                      const Eigen::Vector3d& dh_da, const Eigen::Vector3d& dh_do, double scale,
                      Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>> dtau_dq) {
  const Model& model = *entity.model;
  const int first_dof = entity.first_dof();
  for (int l = above_link; l > 0; l = model.links[l].parent_link) {
    const int k = model.links[l].parent_joint;
    const Joint& joint = model.joints[k];
    if (!joint.movable()) continue;
    const Eigen::Vector3d& ak = data.axis_W[k];
    // A rotation about (ak, ok) turns a and moves o; a translation along ak moves o only.
    double d = rotational(joint.type)
                   ? dh_da.dot(ak.cross(a)) + dh_do.dot(ak.cross(o - data.origin_W[k]))
                   : dh_do.dot(ak);
    dtau_dq[first_dof + joint.dof] += scale * joint.multiplier * d;
  }
  if (!entity.floating()) return;
  for (int i = 0; i < 3; ++i) dtau_dq[Entity::kBasePosition + i] += scale * dh_do[i];
  for (int i = 0; i < 4; ++i) {
    const Eigen::Matrix3d M = data.dR_WB_dquat[i] * data.R_WB.transpose();
    dtau_dq[Entity::kBaseQuaternion + i] +=
        scale * (dh_da.dot(M * a) + dh_do.dot(M * (o - data.p_WB)));
  }
}

}  // namespace

void add_point_load_torque(const Entity& entity, const ModelData& data, int link,
                           const Eigen::Vector3d& p_W, const Eigen::Vector3d& f_W,
                           Eigen::Ref<Eigen::VectorXd> tau, Eigen::Ref<Eigen::MatrixXd> dtau_dq,
                           Eigen::Ref<Eigen::MatrixXd> dtau_dp,
                           Eigen::Ref<Eigen::MatrixXd> dtau_df) {
  const Model& model = *entity.model;
  for (int l = link; l > 0; l = model.links[l].parent_link) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    if (!joint.movable()) continue;
    const int d = joint.dof;
    const double m = joint.multiplier;
    const Eigen::Vector3d& a = data.axis_W[j];
    const Eigen::Vector3d& o = data.origin_W[j];
    if (rotational(joint.type)) {
      // E18 for a revolute joint: J_j(p)^T f = a . ((p - o) x f).
      const Eigen::Vector3d r = p_W - o;
      tau[d] -= m * a.dot(r.cross(f_W));
      dtau_dp.row(d) -= m * f_W.cross(a).transpose();
      dtau_df.row(d) -= m * a.cross(r).transpose();
      // h = a . ((p - o) x f):  dh/da = (p - o) x f,  dh/do = -(f x a).
      add_frame_motion(entity, data, model.links[l].parent_link, a, o, r.cross(f_W), -f_W.cross(a),
                       -m, dtau_dq.row(d));
    } else {
      // Prismatic: J_j(p)^T f = a . f.
      tau[d] -= m * a.dot(f_W);
      dtau_df.row(d) -= m * a.transpose();
      add_frame_motion(entity, data, model.links[l].parent_link, a, o, f_W, Eigen::Vector3d::Zero(),
                       -m, dtau_dq.row(d));
    }
  }
}

namespace {

// r = S_l - M_l o_j: the subtree's first moment about joint j's origin.
Eigen::Vector3d moment_about(const Model& model, const ModelData& data, int link, int joint) {
  return data.subtree_moment_W[link] - model.subtree_mass[link] * data.origin_W[joint];
}

}  // namespace

void add_gravity_torque_values(const Entity& entity, const ModelData& data,
                               const Eigen::Vector3d& g, Eigen::Ref<Eigen::VectorXd> tau) {
  const Model& model = *entity.model;
  for (int l = 1; l < model.num_links(); ++l) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    if (!joint.movable()) continue;
    const Eigen::Vector3d& a = data.axis_W[j];
    tau[joint.dof] -=
        joint.multiplier * (rotational(joint.type) ? a.dot(moment_about(model, data, l, j).cross(g))
                                                   : model.subtree_mass[l] * a.dot(g));
  }
}

void add_gravity_torques(const Entity& entity, const ModelData& data, const Eigen::Vector3d& g,
                         Eigen::Ref<Eigen::VectorXd> tau, Eigen::Ref<Eigen::MatrixXd> dtau_dq) {
  add_gravity_torque_values(entity, data, g, tau);
  const Model& model = *entity.model;
  const int first_dof = entity.first_dof();
  for (int lj = 1; lj < model.num_links(); ++lj) {
    const int j = model.links[lj].parent_joint;
    const Joint& joint = model.joints[j];
    if (!joint.movable()) continue;
    const Eigen::Vector3d& a = data.axis_W[j];
    const double mj = joint.multiplier;
    auto row = dtau_dq.row(joint.dof);
    if (rotational(joint.type)) {
      const Eigen::Vector3d r = moment_about(model, data, lj, j);
      // Joints above j turn a and r together: d[a.(r x g)] = a.(r x (g x a_k)); the root likewise.
      for (int l = model.links[lj].parent_link; l > 0; l = model.links[l].parent_link) {
        const Joint& above = model.joints[model.links[l].parent_joint];
        if (above.movable() && rotational(above.type))
          row[first_dof + above.dof] -=
              mj * above.multiplier *
              a.dot(r.cross(g.cross(data.axis_W[model.links[l].parent_joint])));
      }
      if (entity.floating())
        for (int i = 0; i < 4; ++i) {
          const Eigen::Matrix3d M = data.dR_WB_dquat[i] * data.R_WB.transpose();
          row[Entity::kBaseQuaternion + i] -=
              mj * ((M * a).dot(r.cross(g)) + a.dot((M * r).cross(g)));
        }
    } else {
      const double m = model.subtree_mass[lj];
      for (int l = model.links[lj].parent_link; l > 0; l = model.links[l].parent_link) {
        const int k = model.links[l].parent_joint;
        const Joint& above = model.joints[k];
        if (above.movable() && rotational(above.type))
          row[first_dof + above.dof] -= mj * above.multiplier * m * data.axis_W[k].cross(a).dot(g);
      }
      if (entity.floating())
        for (int i = 0; i < 4; ++i) {
          const Eigen::Matrix3d M = data.dR_WB_dquat[i] * data.R_WB.transpose();
          row[Entity::kBaseQuaternion + i] -= mj * m * (M * a).dot(g);
        }
    }
  }
  // Joints below a revolute joint j (and j itself) move the subtree's moment S: by
  // a_k x (S_k - M_k o_k) for a revolute k, by M_k a_k for a prismatic one.
  for (int lk = 1; lk < model.num_links(); ++lk) {
    const int k = model.links[lk].parent_joint;
    const Joint& below = model.joints[k];
    if (!below.movable()) continue;
    const Eigen::Vector3d dS =
        rotational(below.type)
            ? Eigen::Vector3d(data.axis_W[k].cross(moment_about(model, data, lk, k)))
            : Eigen::Vector3d(model.subtree_mass[lk] * data.axis_W[k]);
    const Eigen::Vector3d dS_x_g = dS.cross(g);
    for (int l = lk; l > 0; l = model.links[l].parent_link) {
      const int j = model.links[l].parent_joint;
      const Joint& joint = model.joints[j];
      if (joint.movable() && rotational(joint.type))
        dtau_dq(joint.dof, first_dof + below.dof) -=
            joint.multiplier * below.multiplier * data.axis_W[j].dot(dS_x_g);
    }
  }
}

void add_point_load_torque_value(const Entity& entity, const ModelData& data, int link,
                                 const Eigen::Vector3d& p_W, const Eigen::Vector3d& f_W,
                                 Eigen::Ref<Eigen::VectorXd> tau) {
  const Model& model = *entity.model;
  for (int l = link; l > 0; l = model.links[l].parent_link) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    if (!joint.movable()) continue;
    const Eigen::Vector3d& a = data.axis_W[j];
    tau[joint.dof] -=
        joint.multiplier *
        (rotational(joint.type) ? a.dot((p_W - data.origin_W[j]).cross(f_W)) : a.dot(f_W));
  }
}

}  // namespace stanceplan
