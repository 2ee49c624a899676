#pragma once
// Everything the constraint blocks and the objective read at one iterate x, computed once per
// new x (forward kinematics, contact frames, forces) and once per Jacobian evaluation (frame,
// vertex and generator Jacobians, centres of mass, joint torques and their gradients).
// Sized at construction; set_x / ensure_* allocate nothing.
#include <Eigen/Core>
#include <array>
#include <vector>

#include "planner/model/model_data.h"
#include "planner/solver/nlp_layout.h"

namespace stanceplan {

// A row of a column-major matrix (non-unit inner stride) or a plain row vector.
using RowRef = Eigen::Ref<Eigen::RowVectorXd, 0, Eigen::InnerStride<>>;

// Link-frame constants of one contact of the request.
struct ContactConstants {
  int e1 = -1, l1 = -1, e2 = -1, l2 = -1;  // entities and links of s1 and s2
  Eigen::Vector3d O1_L, x1_L, y1_L, z1_L;  // s1's frame in l1's frame
  Eigen::Vector3d O2_L, x2_L, y2_L, z2_L;  // s2's frame in l2's frame
  std::vector<Eigen::Vector3d> v1_L;       // s1's vertices in l1's frame
  std::vector<Eigen::Vector2d> v2_S;       // s2's polygon in s2's plane
  std::vector<Eigen::Vector3d> U_L2;       // friction cone generators in l2's frame (E5)
  // s1's radius when it is a point surface (a sphere at its one vertex, surface.h), else 0: the
  // force then acts at p - r z2, one radius below the centre p along s2's normal.
  double radius = 0.0;
};

// World quantities of one contact at the current iterate; Jacobians are over the configuration
// segment of the entity the quantity moves with (e1 for s1's, e2 for s2's and the generators').
struct ContactFrames {
  Eigen::Vector3d O1, x1, y1, z1, O2, x2, y2, z2;
  std::vector<Eigen::Vector3d> p;  // s1's vertices (where forces act)
  std::vector<Eigen::Vector3d> U;  // generators
  std::vector<Eigen::Vector3d> f;  // force at each vertex, by l2 on l1 (loaded contacts)
  Eigen::MatrixXd J_O1, J_x1, J_y1, J_z1, J_O2, J_x2, J_y2, J_z2;
  std::vector<Eigen::MatrixXd> J_p, J_U;
  // d f_j / d(configuration of e2) = sum_k lambda_k J_U[k] (loaded unilateral contacts; zero for a
  // bilateral one, whose force components are variables themselves); ensure_force_jacobians().
  std::vector<Eigen::MatrixXd> J_f;
};

class NlpState {
 public:
  NlpState(const Scene& scene, const PostureRequest& request, const SolverOptions& options,
           const NlpLayout& layout);

  void set_x(const double* x);    // kinematics, frames, forces
  void ensure_jacobians();        // frame/vertex/generator/CoM Jacobians at the current x
  void ensure_force_jacobians();  // ContactFrames::J_f (the analytic Hessian only)
  void ensure_torque_values();    // tau only
  void ensure_torques();          // tau and dtau/dx (calls ensure_jacobians)

  // row.segment(offset(entity), nq) += c^T J for a 3 x nq Jacobian J over `entity`'s segment.
  void add_entity_term(int entity, const Eigen::MatrixXd& J, const Eigen::Vector3d& c,
                       RowRef row) const;
  // The derivative of a loaded contact's vertex force f_j with respect to x, contracted with c:
  // row += c^T df_j/dx (through lambda and the generators' rotation).
  void add_force_term(int task, int vertex, const Eigen::Vector3d& c, RowRef row) const;

  const Scene& scene;
  const PostureRequest& request;
  const SolverOptions& options;
  const NlpLayout& layout;

  Eigen::VectorXd x;
  std::vector<ModelData> data;              // per entity
  std::vector<ContactConstants> constants;  // per request contact
  std::vector<ContactFrames> frames;        // per request contact
  std::vector<Eigen::Vector3d> com;         // per entity
  std::vector<Eigen::MatrixXd> J_com;       // per entity, 3 x nq
  // Per entity (empty for entities without dofs): tau (ndof) and dtau/dx (ndof x n).
  std::vector<Eigen::VectorXd> tau;
  std::vector<Eigen::MatrixXd> dtau_dx;

  // Workspace of the analytic Hessian (PostureNlp::hessian_values): four 3 x max-nq Jacobians for
  // combined vectors, and per entity the weights w of w^T tau that the torque rows and the
  // objective's torque term collect for one pass over the loads (torque_hessian.h).
  std::array<Eigen::MatrixXd, 4> hessian_scratch;
  Eigen::RowVectorXd gradient_scratch;  // 1 x n
  std::vector<Eigen::VectorXd> torque_weights;
  Eigen::MatrixXd torque_gram;  // n x n, lower triangle: (dtau/dx)^T (dtau/dx) of the objective

 private:
  void add_load(int entity, int link, const Eigen::Vector3d& p, const Eigen::Vector3d& f,
                double sign, int task, int vertex);

  template <class LoadVisitor>
  void for_each_load(LoadVisitor visit);

  bool jacobians_ready_ = false;
  bool force_jacobians_ready_ = false;
  bool torque_values_ready_ = false;
  bool torques_ready_ = false;
  // Per entity and link: the dofs of the movable joints above the link (the only torque rows a
  // load on it reaches) and the entity-local columns that move it (the only nonzero Jacobian
  // columns of a point on it).
  std::vector<std::vector<std::vector<int>>> link_dofs_, link_columns_;
  // Scratch for torque assembly.
  std::vector<Eigen::MatrixXd> dtau_dq_;  // per entity ndof x nq
  Eigen::MatrixXd dtau_dp_, dtau_df_;
};

}  // namespace stanceplan
