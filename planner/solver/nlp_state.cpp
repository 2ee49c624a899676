#include "planner/solver/nlp_state.h"

#include <algorithm>
#include <cmath>

#include "planner/model/kinematics.h"
#include "planner/solver/joint_torques.h"

namespace stanceplan {
namespace {

ContactConstants make_constants(const Scene& scene, const ContactTask& task,
                                const SolverOptions& options) {
  const Surface& s1 = scene.surfaces.get(task.contact.s1);
  const Surface& s2 = scene.surfaces.get(task.contact.s2);
  ContactConstants c;
  c.e1 = task.contact.s1.entity;
  c.l1 = s1.link;
  c.e2 = task.contact.s2.entity;
  c.l2 = s2.link;
  c.O1_L = s1.T_LS.translation();
  c.x1_L = s1.T_LS.linear().col(0);
  c.y1_L = s1.T_LS.linear().col(1);
  c.z1_L = s1.T_LS.linear().col(2);
  c.O2_L = s2.T_LS.translation();
  c.x2_L = s2.T_LS.linear().col(0);
  c.y2_L = s2.T_LS.linear().col(1);
  c.z2_L = s2.T_LS.linear().col(2);
  c.v1_L = s1.vertices_L();
  c.v2_S = s2.vertices_S;
  c.radius = s1.radius;
  if (!task.contact.bilateral) {
    // E5: K unit generators on the cone of half-angle atan(mu) around s2's normal, which points
    // from l2 towards l1 (the force l2 exerts on l1 pushes along it).
    const int K = options.cone_generators;
    for (int k = 0; k < K; ++k) {
      const double angle = 2.0 * M_PI * k / K;
      const Eigen::Vector3d u_S(options.friction * std::cos(angle),
                                options.friction * std::sin(angle), 1.0);
      c.U_L2.push_back(s2.T_LS.linear() * u_S.normalized());
    }
  }
  return c;
}

ContactFrames make_frames(const Scene& scene, const ContactConstants& c) {
  ContactFrames f;
  const int n1 = scene.system.entity(c.e1).nq(), n2 = scene.system.entity(c.e2).nq();
  for (Eigen::MatrixXd* J : {&f.J_O1, &f.J_x1, &f.J_y1, &f.J_z1}) J->setZero(3, n1);
  for (Eigen::MatrixXd* J : {&f.J_O2, &f.J_x2, &f.J_y2, &f.J_z2}) J->setZero(3, n2);
  f.p.resize(c.v1_L.size());
  f.f.assign(c.v1_L.size(), Eigen::Vector3d::Zero());
  f.J_p.assign(c.v1_L.size(), Eigen::MatrixXd::Zero(3, n1));
  f.U.resize(c.U_L2.size());
  f.J_U.assign(c.U_L2.size(), Eigen::MatrixXd::Zero(3, n2));
  f.J_f.assign(c.v1_L.size(), Eigen::MatrixXd::Zero(3, n2));
  return f;
}

}  // namespace

NlpState::NlpState(const Scene& scene_, const PostureRequest& request_,
                   const SolverOptions& options_, const NlpLayout& layout_)
    : scene(scene_), request(request_), options(options_), layout(layout_), x(layout_.n) {
  const System& system = scene.system;
  int max_dof = 0;
  for (const Entity& e : system.entities()) {
    data.emplace_back(e);
    com.push_back(Eigen::Vector3d::Zero());
    J_com.push_back(Eigen::MatrixXd::Zero(3, e.nq()));
    const int ndof = e.model->num_dofs();
    tau.push_back(Eigen::VectorXd::Zero(ndof));
    dtau_dx.push_back(Eigen::MatrixXd::Zero(ndof, ndof > 0 ? layout.n : 0));
    dtau_dq_.push_back(Eigen::MatrixXd::Zero(ndof, e.nq()));
    max_dof = std::max(max_dof, ndof);
  }
  for (const ContactTask& task : request.contacts) {
    constants.push_back(make_constants(scene, task, options));
    frames.push_back(make_frames(scene, constants.back()));
  }
  for (const Entity& e : system.entities()) {
    const Model& model = *e.model;
    link_dofs_.emplace_back(model.num_links());
    link_columns_.emplace_back(model.num_links());
    for (int link = 0; link < model.num_links(); ++link) {
      std::vector<int>& dofs = link_dofs_.back()[link];
      for (int l = link; l > 0; l = model.links[l].parent_link) {
        const Joint& joint = model.joints[model.links[l].parent_joint];
        if (joint.movable() && std::find(dofs.begin(), dofs.end(), joint.dof) == dofs.end())
          dofs.push_back(joint.dof);
      }
      std::vector<int>& columns = link_columns_.back()[link];
      for (int i = 0; i < e.first_dof(); ++i) columns.push_back(i);
      for (int d : dofs) columns.push_back(e.first_dof() + d);
    }
  }
  dtau_dp_.setZero(max_dof, 3);
  dtau_df_.setZero(max_dof, 3);
  int max_nq = 0;
  for (const Entity& e : system.entities()) max_nq = std::max(max_nq, e.nq());
  for (Eigen::MatrixXd& J : hessian_scratch) J.setZero(3, max_nq);
  gradient_scratch.setZero(layout.n);
  torque_gram.setZero(layout.n, layout.n);
  for (const Entity& e : system.entities())
    torque_weights.push_back(Eigen::VectorXd::Zero(e.model->num_dofs()));
}

void NlpState::set_x(const double* x_in) {
  x = Eigen::Map<const Eigen::VectorXd>(x_in, layout.n);
  const System& system = scene.system;
  for (int e = 0; e < system.num_entities(); ++e)
    forward_kinematics(system.entity(e), x.segment(system.offset(e), system.entity(e).nq()),
                       data[e]);
  for (size_t t = 0; t < frames.size(); ++t) {
    const ContactConstants& c = constants[t];
    ContactFrames& f = frames[t];
    const Eigen::Isometry3d& T1 = data[c.e1].T_WL[c.l1];
    const Eigen::Isometry3d& T2 = data[c.e2].T_WL[c.l2];
    f.O1 = T1 * c.O1_L;
    f.x1 = T1.linear() * c.x1_L;
    f.y1 = T1.linear() * c.y1_L;
    f.z1 = T1.linear() * c.z1_L;
    f.O2 = T2 * c.O2_L;
    f.x2 = T2.linear() * c.x2_L;
    f.y2 = T2.linear() * c.y2_L;
    f.z2 = T2.linear() * c.z2_L;
    for (size_t j = 0; j < c.v1_L.size(); ++j) f.p[j] = T1 * c.v1_L[j];
    for (size_t k = 0; k < c.U_L2.size(); ++k) f.U[k] = T2.linear() * c.U_L2[k];
    const int b = layout.force_block_of_task[t];
    if (b < 0) continue;
    const ForceBlock& block = layout.forces[b];
    for (int j = 0; j < block.num_vertices; ++j) {
      const auto lambda = x.segment(block.first_column + j * block.per_vertex, block.per_vertex);
      if (block.bilateral) {
        f.f[j] = lambda;  // world components (free force, no E7)
      } else {
        f.f[j].setZero();
        for (int k = 0; k < block.per_vertex; ++k) f.f[j] += lambda[k] * f.U[k];  // E5
      }
    }
  }
  for (int e = 0; e < system.num_entities(); ++e)
    com[e] = center_of_mass(system.entity(e), data[e]);
  jacobians_ready_ = false;
  force_jacobians_ready_ = false;
  torque_values_ready_ = false;
  torques_ready_ = false;
}

void NlpState::ensure_jacobians() {
  if (jacobians_ready_) return;
  const System& system = scene.system;
  for (size_t t = 0; t < frames.size(); ++t) {
    const ContactConstants& c = constants[t];
    ContactFrames& f = frames[t];
    const Entity& E1 = system.entity(c.e1);
    const Entity& E2 = system.entity(c.e2);
    point_jacobian(E1, data[c.e1], c.l1, c.O1_L, f.J_O1);
    vector_jacobian(E1, data[c.e1], c.l1, c.x1_L, f.J_x1);
    vector_jacobian(E1, data[c.e1], c.l1, c.y1_L, f.J_y1);
    vector_jacobian(E1, data[c.e1], c.l1, c.z1_L, f.J_z1);
    point_jacobian(E2, data[c.e2], c.l2, c.O2_L, f.J_O2);
    vector_jacobian(E2, data[c.e2], c.l2, c.x2_L, f.J_x2);
    vector_jacobian(E2, data[c.e2], c.l2, c.y2_L, f.J_y2);
    vector_jacobian(E2, data[c.e2], c.l2, c.z2_L, f.J_z2);
    for (size_t j = 0; j < c.v1_L.size(); ++j)
      point_jacobian(E1, data[c.e1], c.l1, c.v1_L[j], f.J_p[j]);
    for (size_t k = 0; k < c.U_L2.size(); ++k)
      vector_jacobian(E2, data[c.e2], c.l2, c.U_L2[k], f.J_U[k]);
  }
  for (int e = 0; e < system.num_entities(); ++e)
    center_of_mass_jacobian(system.entity(e), data[e], J_com[e]);
  jacobians_ready_ = true;
}

void NlpState::ensure_force_jacobians() {
  if (force_jacobians_ready_) return;
  ensure_jacobians();
  for (size_t t = 0; t < frames.size(); ++t) {
    const int b = layout.force_block_of_task[t];
    if (b < 0 || layout.forces[b].bilateral) continue;
    const ForceBlock& block = layout.forces[b];
    ContactFrames& f = frames[t];
    for (int j = 0; j < block.num_vertices; ++j) {
      f.J_f[j].setZero();
      for (int k = 0; k < block.per_vertex; ++k)
        f.J_f[j] += x[block.first_column + j * block.per_vertex + k] * f.J_U[k];
    }
  }
  force_jacobians_ready_ = true;
}

void NlpState::add_entity_term(int entity, const Eigen::MatrixXd& J, const Eigen::Vector3d& c,
                               RowRef row) const {
  const int nq = static_cast<int>(J.cols());
  if (nq == 0) return;
  row.segment(scene.system.offset(entity), nq).noalias() += c.transpose() * J;
}

void NlpState::add_force_term(int task, int vertex, const Eigen::Vector3d& c, RowRef row) const {
  const ForceBlock& block = layout.forces[layout.force_block_of_task[task]];
  const int first = block.first_column + vertex * block.per_vertex;
  if (block.bilateral) {
    row.segment<3>(first) += c.transpose();
    return;
  }
  const ContactFrames& f = frames[task];
  const int e2 = constants[task].e2;
  for (int k = 0; k < block.per_vertex; ++k) {
    row[first + k] += c.dot(f.U[k]);
    add_entity_term(e2, f.J_U[k], x[first + k] * c, row);  // generators turn with l2
  }
}

void NlpState::add_load(int entity, int link, const Eigen::Vector3d& p, const Eigen::Vector3d& f,
                        double sign, int task, int vertex) {
  const Entity& E = scene.system.entity(entity);
  const int ndof = E.model->num_dofs();
  auto dp = dtau_dp_.topRows(ndof);
  auto df = dtau_df_.topRows(ndof);
  const std::vector<int>& rows = link_dofs_[entity][link];  // only these rows are reached
  for (int d : rows) {
    dp.row(d).setZero();
    df.row(d).setZero();
  }
  add_point_load_torque(E, data[entity], link, p, sign * f, tau[entity], dtau_dq_[entity], dp, df);
  Eigen::MatrixXd& D = dtau_dx[entity];
  const ContactConstants& c = constants[task];
  const ContactFrames& fr = frames[task];
  // Chain rule through the load point p = s1's vertex - r z2, over the columns that move it only:
  // the vertex moves with l1, the point contact's offset -r z2 with l2 ...
  const int offset1 = scene.system.offset(c.e1);
  for (int col : link_columns_[c.e1][c.l1])
    for (int d : rows) D(d, offset1 + col) += dp.row(d).dot(fr.J_p[vertex].col(col));
  if (c.radius > 0.0) {
    const int offset2 = scene.system.offset(c.e2);
    for (int col : link_columns_[c.e2][c.l2])
      for (int d : rows) D(d, offset2 + col) -= c.radius * dp.row(d).dot(fr.J_z2.col(col));
  }
  // ... and through the force.
  for (int d : rows) add_force_term(task, vertex, sign * df.row(d).transpose(), D.row(d));
}

// Calls visit(entity, link, point, force, sign, task, vertex) for every contact load a robot
// receives: +f on s1's entity, -f on s2's entity, both at s1's vertex (E18). A point contact's
// load point is its centre less r z2 (the couple -r z2 x f of the force taken at the centre).
template <class LoadVisitor>
void NlpState::for_each_load(LoadVisitor visit) {
  const System& system = scene.system;
  for (size_t t = 0; t < frames.size(); ++t) {
    if (layout.force_block_of_task[t] < 0) continue;
    const ContactConstants& c = constants[t];
    const ContactFrames& fr = frames[t];
    for (size_t j = 0; j < fr.p.size(); ++j) {
      const Eigen::Vector3d p = fr.p[j] - c.radius * fr.z2;
      if (system.entity(c.e1).model->num_dofs() > 0)
        visit(c.e1, c.l1, p, fr.f[j], 1.0, int(t), int(j));
      if (system.entity(c.e2).model->num_dofs() > 0)
        visit(c.e2, c.l2, p, fr.f[j], -1.0, int(t), int(j));
    }
  }
}

void NlpState::ensure_torque_values() {
  if (torque_values_ready_) return;
  for (int e = 0; e < scene.system.num_entities(); ++e) {
    tau[e].setZero();
    if (tau[e].size() > 0)
      add_gravity_torque_values(scene.system.entity(e), data[e], scene.gravity, tau[e]);
  }
  for_each_load([&](int e, int link, const Eigen::Vector3d& p, const Eigen::Vector3d& f,
                    double sign, int, int) {
    add_point_load_torque_value(scene.system.entity(e), data[e], link, p, sign * f, tau[e]);
  });
  torque_values_ready_ = true;
}

void NlpState::ensure_torques() {
  if (torques_ready_) return;
  ensure_jacobians();
  const System& system = scene.system;
  for (int e = 0; e < system.num_entities(); ++e) {
    tau[e].setZero();
    dtau_dx[e].setZero();
    dtau_dq_[e].setZero();
    if (tau[e].size() > 0)
      add_gravity_torques(system.entity(e), data[e], scene.gravity, tau[e], dtau_dq_[e]);
  }
  for_each_load([&](int e, int link, const Eigen::Vector3d& p, const Eigen::Vector3d& f,
                    double sign, int task,
                    int vertex) { add_load(e, link, p, f, sign, task, vertex); });
  for (int e = 0; e < system.num_entities(); ++e)
    if (dtau_dq_[e].size() > 0)
      dtau_dx[e].middleCols(system.offset(e), system.entity(e).nq()) += dtau_dq_[e];
  torque_values_ready_ = true;
  torques_ready_ = true;
}

}  // namespace stanceplan
