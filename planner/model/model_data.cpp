#include "planner/model/model_data.h"

namespace stanceplan {

ModelData::ModelData(const Entity& entity)
    : T_WL(entity.model->links.size(), Eigen::Isometry3d::Identity()),
      joint_position(entity.model->joints.size(), 0.0),
      axis_W(entity.model->joints.size(), Eigen::Vector3d::Zero()),
      origin_W(entity.model->joints.size(), Eigen::Vector3d::Zero()),
      subtree_moment_W(entity.model->links.size(), Eigen::Vector3d::Zero()) {
  for (Eigen::Matrix3d& d : dR_WB_dquat) d.setZero();
}

}  // namespace stanceplan
