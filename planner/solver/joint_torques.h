#pragma once
// Joint torques that hold a robot against point loads (E18) and their derivatives (paper
// Appendix A, the derivatives of the torque Jacobians Upsilon). Convention of docs/PLAN_FORMAT.md:
//   tau + sum_loads J(p)^T f = 0,   so every load f received at p contributes  tau -= J(p)^T f.
// Gravity is a load too: m_i g received at link i's centre of mass.
#include <Eigen/Core>

#include "planner/model/entity.h"
#include "planner/model/model_data.h"

namespace stanceplan {

// Adds the contribution of force f_W received at point p_W (fixed to `link`) to tau (one entry per
// dof of the entity) and the partial derivatives:
//   dtau_dq (ndof x entity.nq()): through the joint axes and origins, p_W and f_W held fixed;
//   dtau_dp (ndof x 3) and dtau_df (ndof x 3).
// Mimic joints add multiplier x their torque to their source's dof. Allocates nothing.
void add_point_load_torque(const Entity& entity, const ModelData& data, int link,
                           const Eigen::Vector3d& p_W, const Eigen::Vector3d& f_W,
                           Eigen::Ref<Eigen::VectorXd> tau, Eigen::Ref<Eigen::MatrixXd> dtau_dq,
                           Eigen::Ref<Eigen::MatrixXd> dtau_dp,
                           Eigen::Ref<Eigen::MatrixXd> dtau_df);

// Gravity's contribution (E18, the -dC/dtheta^T m g term) from the subtree moments of
// forward_kinematics: joint j holds M_l (c_l - o_j) x g for the subtree below it. With derivatives
// with respect to the entity's configuration (dtau_dq: ndof x nq) in O(dofs x depth).
void add_gravity_torques(const Entity& entity, const ModelData& data, const Eigen::Vector3d& g,
                         Eigen::Ref<Eigen::VectorXd> tau, Eigen::Ref<Eigen::MatrixXd> dtau_dq);
void add_gravity_torque_values(const Entity& entity, const ModelData& data,
                               const Eigen::Vector3d& g, Eigen::Ref<Eigen::VectorXd> tau);

// The torque contribution alone (no derivatives).
void add_point_load_torque_value(const Entity& entity, const ModelData& data, int link,
                                 const Eigen::Vector3d& p_W, const Eigen::Vector3d& f_W,
                                 Eigen::Ref<Eigen::VectorXd> tau);

}  // namespace stanceplan
