#pragma once
// The pieces every constraint block's analytic Hessian is made of (ConstraintBlock::add_hessian).
// Every world quantity of the program is a point or a vector fixed to a link, or a vertex force
// f = sum_k lambda_k U_k (E5) whose generators turn with s2's link, so the Hessian of a product of
// two of them is (a) each one's own curvature contracted with the other (second-order
// kinematics, planner/model/kinematics_hessian.h) plus (b) the product of their first
// derivatives. H is the n x n Hessian over x = [q | lambda]; every function adds to BOTH
// triangles (the caller reads the lower one).
#include <Eigen/Core>

#include "planner/solver/nlp_state.h"

namespace stanceplan {

// (a) H += d2(c . p)/dq2 over `entity`'s columns, p_W a point fixed to `link`.
void add_point_curvature(const NlpState& state, int entity, int link, const Eigen::Vector3d& p_W,
                         const Eigen::Vector3d& c, Eigen::Ref<Eigen::MatrixXd> H);
// (a) H += d2(c . v)/dq2, v_W a vector fixed to `link`. Linear in v_W: a sum of vectors fixed to
// one link (e.g. a vertex force, sum_k lambda_k U_k with lambda held) is one call.
void add_vector_curvature(const NlpState& state, int entity, int link, const Eigen::Vector3d& v_W,
                          const Eigen::Vector3d& c, Eigen::Ref<Eigen::MatrixXd> H);
// (b) for a^T M b with a moving with ea (J_a) and b with eb (J_b):
//     H(ea, eb) += J_a^T M J_b,  H(eb, ea) += J_b^T M^T J_a.
void add_cross_curvature(const NlpState& state, int ea,
                         const Eigen::Ref<const Eigen::MatrixXd>& J_a, int eb,
                         const Eigen::Ref<const Eigen::MatrixXd>& J_b, const Eigen::Matrix3d& M,
                         Eigen::Ref<Eigen::MatrixXd> H);
// H(column, entity) += c^T J and its mirror: the mixed derivative of (variable x[column]) * (c . w)
// for a world quantity w moving with `entity` (Jacobian J).
void add_column_curvature(const NlpState& state, int column, int entity,
                          const Eigen::Ref<const Eigen::MatrixXd>& J, const Eigen::Vector3d& c,
                          Eigen::Ref<Eigen::MatrixXd> H);
// The curvature of c . f_j for a loaded vertex force, c held fixed: lambda-q through the turning
// generators (J_U[k]^T c) and q-q (the vector curvature of f_j on s2's link).
void add_force_curvature(const NlpState& state, int task, int vertex, const Eigen::Vector3d& c,
                         Eigen::Ref<Eigen::MatrixXd> H);
// The mixed terms of a^T M f_j for a world quantity a moving with ea (J_a): q_ea-q_e2 through
// J_f, and q_ea-lambda through the generators (or the free components of a bilateral force).
// Together with add_force_curvature(M^T a) and a's own curvature (contracted with M f_j) this is
// the whole Hessian of a^T M f_j.
void add_force_cross_curvature(const NlpState& state, int ea,
                               const Eigen::Ref<const Eigen::MatrixXd>& J_a, int task, int vertex,
                               const Eigen::Matrix3d& M, Eigen::Ref<Eigen::MatrixXd> H);
// The whole Hessian of scale * (a . b), a and b vectors fixed to links ea/la and eb/lb.
void add_vector_dot_curvature(const NlpState& state, int ea, int la, const Eigen::Vector3d& a,
                              const Eigen::Ref<const Eigen::MatrixXd>& J_a, int eb, int lb,
                              const Eigen::Vector3d& b,
                              const Eigen::Ref<const Eigen::MatrixXd>& J_b, double scale,
                              Eigen::Ref<Eigen::MatrixXd> H);
// The whole Hessian of scale * ((p1 - O2) . b) for contact `task`: p1 a point fixed to s1's link
// (its origin O1 for E9-E11 and obj4, a vertex for the polygon rows), s2's origin O2 and the
// vector b fixed to s2's link.
void add_offset_dot_curvature(const NlpState& state, int task, const Eigen::Vector3d& p1,
                              const Eigen::Ref<const Eigen::MatrixXd>& J_p1,
                              const Eigen::Vector3d& b,
                              const Eigen::Ref<const Eigen::MatrixXd>& J_b, double scale,
                              Eigen::Ref<Eigen::MatrixXd> H);
// H += d2(c . C)/dq2 for the centre of mass C of `entity`.
void add_com_curvature(const NlpState& state, int entity, const Eigen::Vector3d& c,
                       Eigen::Ref<Eigen::MatrixXd> H);

// [v]x, the cross-product matrix: [v]x w = v x w.
Eigen::Matrix3d cross_matrix(const Eigen::Vector3d& v);

}  // namespace stanceplan
