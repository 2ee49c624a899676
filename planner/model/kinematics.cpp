#include "planner/model/kinematics.h"

#include "planner/model/quaternion.h"

namespace stanceplan {
namespace {

// Motion of the child frame relative to the joint frame for a joint value.
Eigen::Isometry3d joint_motion(const Joint& joint, double value) {
  Eigen::Isometry3d M = Eigen::Isometry3d::Identity();
  switch (joint.type) {
    case JointType::Revolute:
    case JointType::Continuous:
      M.linear() = Eigen::AngleAxisd(value, joint.axis).toRotationMatrix();
      break;
    case JointType::Prismatic:
      M.translation() = value * joint.axis;
      break;
    case JointType::Fixed:
      break;
  }
  return M;
}

bool is_rotational(JointType type) {
  return type == JointType::Revolute || type == JointType::Continuous;
}

}  // namespace

void forward_kinematics(const Entity& entity, const Eigen::Ref<const Eigen::VectorXd>& q,
                        ModelData& data) {
  const Model& model = *entity.model;
  if (entity.floating()) {
    const Eigen::Vector4d quat = q.segment<4>(Entity::kBaseQuaternion);
    data.p_WB = q.segment<3>(Entity::kBasePosition);
    data.quaternion_WB = quat;
    data.R_WB = rotation_from_quaternion(quat);
    rotation_quaternion_derivatives(quat, &data.dR_WB_dquat);
  } else {
    data.p_WB = entity.T_WB.translation();
    data.R_WB = entity.T_WB.linear();
  }
  data.T_WL[0].linear() = data.R_WB;
  data.T_WL[0].translation() = data.p_WB;
  const int first_dof = entity.first_dof();
  for (int i = 1; i < model.num_links(); ++i) {
    const Link& link = model.links[i];
    const int j = link.parent_joint;
    const Joint& joint = model.joints[j];
    const Eigen::Isometry3d T_WJ = data.T_WL[link.parent_link] * joint.T_PJ;
    double value = 0.0;
    if (joint.movable()) value = joint.multiplier * q[first_dof + joint.dof] + joint.offset;
    data.joint_position[j] = value;
    data.axis_W[j] = T_WJ.linear() * joint.axis;
    data.origin_W[j] = T_WJ.translation();
    data.T_WL[i] = T_WJ * joint_motion(joint, value);
  }
  for (int i = model.num_links() - 1; i >= 0; --i) {
    const Inertial& inertial = model.links[i].inertial;
    data.subtree_moment_W[i] = inertial.mass * (data.T_WL[i] * inertial.p_LC);
  }
  for (int i = model.num_links() - 1; i > 0; --i)
    data.subtree_moment_W[model.links[i].parent_link] += data.subtree_moment_W[i];
}

std::vector<ModelData> system_kinematics(const System& system, const Eigen::VectorXd& q) {
  std::vector<ModelData> data;
  data.reserve(system.num_entities());
  for (int e = 0; e < system.num_entities(); ++e) {
    data.emplace_back(system.entity(e));
    forward_kinematics(system.entity(e), q.segment(system.offset(e), system.entity(e).nq()),
                       data.back());
  }
  return data;
}

void point_jacobian_world(const Entity& entity, const ModelData& data, int link,
                          const Eigen::Vector3d& p_W, Eigen::Ref<Eigen::MatrixXd> J) {
  const Model& model = *entity.model;
  J.setZero();
  if (entity.floating()) {
    // p_W = p_WB + R_WB(phi) p_B with p_B fixed in the root frame (E27-E29).
    J.block<3, 3>(0, Entity::kBasePosition).setIdentity();
    const Eigen::Vector3d p_B = data.R_WB.transpose() * (p_W - data.p_WB);
    for (int k = 0; k < 4; ++k) J.col(Entity::kBaseQuaternion + k) = data.dR_WB_dquat[k] * p_B;
  }
  const int first_dof = entity.first_dof();
  for (int l = link; l > 0; l = model.links[l].parent_link) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    if (!joint.movable()) continue;
    // E30-E31: a revolute joint moves the point by a x (p - o); a prismatic one along a.
    if (is_rotational(joint.type))
      J.col(first_dof + joint.dof) +=
          joint.multiplier * data.axis_W[j].cross(p_W - data.origin_W[j]);
    else
      J.col(first_dof + joint.dof) += joint.multiplier * data.axis_W[j];
  }
}

void point_jacobian(const Entity& entity, const ModelData& data, int link,
                    const Eigen::Vector3d& p_L, Eigen::Ref<Eigen::MatrixXd> J) {
  point_jacobian_world(entity, data, link, data.T_WL[link] * p_L, J);
}

void vector_jacobian(const Entity& entity, const ModelData& data, int link,
                     const Eigen::Vector3d& v_L, Eigen::Ref<Eigen::MatrixXd> J) {
  const Model& model = *entity.model;
  const Eigen::Vector3d v_W = data.T_WL[link].linear() * v_L;
  J.setZero();
  if (entity.floating()) {
    const Eigen::Vector3d v_B = data.R_WB.transpose() * v_W;
    for (int k = 0; k < 4; ++k) J.col(Entity::kBaseQuaternion + k) = data.dR_WB_dquat[k] * v_B;
  }
  const int first_dof = entity.first_dof();
  for (int l = link; l > 0; l = model.links[l].parent_link) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    // E32-E33: only rotations turn a link-fixed vector.
    if (joint.movable() && is_rotational(joint.type))
      J.col(first_dof + joint.dof) += joint.multiplier * data.axis_W[j].cross(v_W);
  }
}

Eigen::Vector3d center_of_mass(const Entity& entity, const ModelData& data) {
  const Model& model = *entity.model;
  return model.total_mass > 0.0 ? Eigen::Vector3d(data.subtree_moment_W[0] / model.total_mass)
                                : data.p_WB;
}

void center_of_mass_jacobian(const Entity& entity, const ModelData& data,
                             Eigen::Ref<Eigen::MatrixXd> J) {
  const Model& model = *entity.model;
  J.setZero();
  if (model.total_mass <= 0.0) return;
  const double inv_mass = 1.0 / model.total_mass;
  if (entity.floating()) {
    J.block<3, 3>(0, Entity::kBasePosition).setIdentity();
    const Eigen::Vector3d c_B = data.R_WB.transpose() * (center_of_mass(entity, data) - data.p_WB);
    for (int k = 0; k < 4; ++k) J.col(Entity::kBaseQuaternion + k) = data.dR_WB_dquat[k] * c_B;
  }
  const int first_dof = entity.first_dof();
  for (int l = 1; l < model.num_links(); ++l) {
    const int j = model.links[l].parent_joint;
    const Joint& joint = model.joints[j];
    if (!joint.movable()) continue;
    // Joint j moves the subtree below it: M_l (c_l - o_j) turns about a_j, or M_l slides along it.
    const double m = model.subtree_mass[l];
    const Eigen::Vector3d& a = data.axis_W[j];
    J.col(first_dof + joint.dof) +=
        joint.multiplier * inv_mass *
        (is_rotational(joint.type)
             ? Eigen::Vector3d(a.cross(data.subtree_moment_W[l] - m * data.origin_W[j]))
             : Eigen::Vector3d(m * a));
  }
}

}  // namespace stanceplan
