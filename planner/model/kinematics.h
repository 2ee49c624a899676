#pragma once
// Forward kinematics and first-order derivatives of one entity (paper Appendix A, E27-E35).
// q is the entity's own configuration segment (see Entity for its layout); every Jacobian is
// 3 x entity.nq() and is overwritten. After forward_kinematics nothing here allocates.
#include <Eigen/Core>

#include "planner/model/entity.h"
#include "planner/model/model_data.h"
#include "planner/model/system.h"

#include <vector>

namespace stanceplan {

void forward_kinematics(const Entity& entity, const Eigen::Ref<const Eigen::VectorXd>& q,
                        ModelData& data);

// Forward kinematics of every entity of a system at the full configuration q (allocates: for
// checks and set-up, not for solver callbacks).
std::vector<ModelData> system_kinematics(const System& system, const Eigen::VectorXd& q);

// d p_W / dq for the point rigidly attached to `link` that is at p_W (world) now.
void point_jacobian_world(const Entity& entity, const ModelData& data, int link,
                          const Eigen::Vector3d& p_W, Eigen::Ref<Eigen::MatrixXd> J);
// Same, for a point given in the link frame.
void point_jacobian(const Entity& entity, const ModelData& data, int link,
                    const Eigen::Vector3d& p_L, Eigen::Ref<Eigen::MatrixXd> J);
// d (R_WL v_L) / dq for a vector fixed in the link frame (normals, surface axes).
void vector_jacobian(const Entity& entity, const ModelData& data, int link,
                     const Eigen::Vector3d& v_L, Eigen::Ref<Eigen::MatrixXd> J);

Eigen::Vector3d center_of_mass(const Entity& entity, const ModelData& data);
// d C / dq, from the subtree moments: a joint moves the CoM of everything below it.
void center_of_mass_jacobian(const Entity& entity, const ModelData& data,
                             Eigen::Ref<Eigen::MatrixXd> J);

}  // namespace stanceplan
