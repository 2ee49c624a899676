#pragma once
// Second and third derivatives of link-fixed points and vectors with respect to one entity's
// configuration q (entity.nq(): the floating root [p_WB (3), phi (4)] when there is one, then the
// dofs), contracted with fixed world vectors: what the analytic Hessian of the IK-statics program
// needs (kinematics.h has the first derivatives, E27-E35).
//
// Every H is entity.nq() x entity.nq(), symmetric, and both triangles are ADDED to (scaled by
// `scale`); every J is 3 x entity.nq() and is overwritten. Joint rates w have one entry per dof of
// the entity (Model::num_dofs(), no root entries); a mimic joint moves with multiplier x its
// source's rate. The root quaternion phi is not assumed normalised (R(phi) = R(phi / |phi|),
// quaternion.h). Nothing here allocates.
#include <Eigen/Core>

#include "planner/model/entity.h"
#include "planner/model/model_data.h"

namespace stanceplan {

// H += scale * d2(c . p)/dq2 for the point fixed to `link` that is at p_W now.
void add_point_hessian(const Entity& entity, const ModelData& data, int link,
                       const Eigen::Vector3d& p_W, const Eigen::Vector3d& c_W, double scale,
                       Eigen::Ref<Eigen::MatrixXd> H);

// H += scale * d2(c . v)/dq2 for the vector fixed to `link` that is v_W now (an axis, a normal).
void add_vector_hessian(const Entity& entity, const ModelData& data, int link,
                        const Eigen::Vector3d& v_W, const Eigen::Vector3d& c_W, double scale,
                        Eigen::Ref<Eigen::MatrixXd> H);

// The velocity of the point under joint rates w, v = J_p(q) [0; w] (the root at rest), and
// J_v = dv/dq (second derivatives of the point). Returns v.
Eigen::Vector3d point_velocity_jacobian(const Entity& entity, const ModelData& data, int link,
                                        const Eigen::Vector3d& p_W,
                                        const Eigen::Ref<const Eigen::VectorXd>& w,
                                        Eigen::Ref<Eigen::MatrixXd> J_v);

// H += scale * d2(c . v)/dq2 with v the point's velocity under w (third derivatives of the point).
// With c = f this is the Hessian of w^T (J_p^T f), a load's joint torques (E18) weighted by w.
void add_point_velocity_hessian(const Entity& entity, const ModelData& data, int link,
                                const Eigen::Vector3d& p_W,
                                const Eigen::Ref<const Eigen::VectorXd>& w,
                                const Eigen::Vector3d& c_W, double scale,
                                Eigen::Ref<Eigen::MatrixXd> H);

// The centre of mass C (kinematics.h center_of_mass): H += scale * d2(c . C)/dq2.
void add_com_hessian(const Entity& entity, const ModelData& data, const Eigen::Vector3d& c_W,
                     double scale, Eigen::Ref<Eigen::MatrixXd> H);

// The centre of mass's velocity under w, v_C = J_C(q) [0; w], and J_v = dv_C/dq. Returns v_C.
// Gravity's joint torques weighted by w are w^T tau_g = -M g . v_C (joint_torques.h convention).
Eigen::Vector3d com_velocity_jacobian(const Entity& entity, const ModelData& data,
                                      const Eigen::Ref<const Eigen::VectorXd>& w,
                                      Eigen::Ref<Eigen::MatrixXd> J_v);

// H += scale * d2(c . v_C)/dq2 with v_C the centre of mass's velocity under w.
void add_com_velocity_hessian(const Entity& entity, const ModelData& data,
                              const Eigen::Ref<const Eigen::VectorXd>& w,
                              const Eigen::Vector3d& c_W, double scale,
                              Eigen::Ref<Eigen::MatrixXd> H);

}  // namespace stanceplan
