#pragma once
// Mutable workspace for one entity's kinematics (the "data" of the model/data split). Sized once
// from the model; forward_kinematics and the Jacobian functions then allocate nothing.
#include <Eigen/Geometry>
#include <array>
#include <vector>

#include "planner/model/entity.h"

namespace stanceplan {

struct ModelData {
  explicit ModelData(const Entity& entity);

  std::vector<Eigen::Isometry3d> T_WL;    // world pose of every link
  std::vector<double> joint_position;     // every joint's value (mimic applied), 0 for fixed
  std::vector<Eigen::Vector3d> axis_W;    // every joint's axis in the world frame
  std::vector<Eigen::Vector3d> origin_W;  // every joint frame's origin in the world frame
  // Per link: first mass moment of its subtree, sum of m_i c_i over the link and its descendants
  // (world frame). subtree_moment_W[0] / total mass is the centre of mass.
  std::vector<Eigen::Vector3d> subtree_moment_W;
  // Root orientation and its derivative with respect to the 4 quaternion components (floating).
  Eigen::Matrix3d R_WB = Eigen::Matrix3d::Identity();
  // The configuration's root quaternion (w, x, y, z) as given, not normalised (floating only):
  // second derivatives of R(phi) need phi itself (kinematics_hessian.h).
  Eigen::Vector4d quaternion_WB = Eigen::Vector4d(1, 0, 0, 0);
  Eigen::Vector3d p_WB = Eigen::Vector3d::Zero();
  std::array<Eigen::Matrix3d, 4> dR_WB_dquat;
};

}  // namespace stanceplan
