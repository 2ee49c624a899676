#include "planner/guide/approach.h"

#include <Eigen/Geometry>
#include <cmath>

#include "planner/model/kinematics.h"

namespace stanceplan {
namespace {

// Entity e's own surface in contact c, when c is between e and another entity.
std::optional<SurfaceRef> own_surface(const Contact& c, int e) {
  if ((c.s1.entity == e) == (c.s2.entity == e)) return std::nullopt;
  return c.s1.entity == e ? c.s1 : c.s2;
}

double heading(const Eigen::Matrix3d& R_WS) {
  return std::atan2(R_WS(1, 0), R_WS(0, 0));
}

// Moves robot e of q (at the goal) back to its initial joints and carries its root so that the
// kept surfaces' mean origin and heading are those of the goal posture (E10-E13: a planar contact
// fixes the surface's height and tilt, so only the ground-plane move and the heading are free).
void carry_to_goal(const Problem& problem, int e, const std::vector<SurfaceRef>& kept,
                   const std::vector<ModelData>& at_goal, bool limbs_only, double back_off,
                   Eigen::VectorXd& q) {
  const System& system = problem.scene.system;
  const int o = system.offset(e);
  const Entity& entity = system.entity(e);
  const Model& model = *entity.model;
  // The joints between the root and the kept surfaces (the legs) stand as they start; the others
  // (arms, chest) stay as at the goal when `limbs_only`.
  std::vector<bool> standing(size_t(model.num_dofs()), !limbs_only);
  for (const SurfaceRef& ref : kept)
    for (int l = problem.scene.surfaces.get(ref).link; l > 0;
         l = model.links[size_t(l)].parent_link)
      if (const int j = model.links[size_t(l)].parent_joint;
          j >= 0 && model.joints[size_t(j)].dof >= 0)
        standing[size_t(model.joints[size_t(j)].dof)] = true;
  for (int k = 0; k < model.num_dofs(); ++k)
    if (standing[size_t(k)])
      q[o + entity.first_dof() + k] = problem.initial_configuration[o + entity.first_dof() + k];
  const std::vector<ModelData> at_start = system_kinematics(system, problem.initial_configuration);
  Eigen::Vector3d from = Eigen::Vector3d::Zero(), to = Eigen::Vector3d::Zero();
  double s = 0.0, c = 0.0;
  for (const SurfaceRef& ref : kept) {
    const Surface& surface = problem.scene.surfaces.get(ref);
    const Eigen::Isometry3d T0 = at_start[size_t(e)].T_WL[size_t(surface.link)] * surface.T_LS;
    const Eigen::Isometry3d T1 = at_goal[size_t(e)].T_WL[size_t(surface.link)] * surface.T_LS;
    from += T0.translation() / double(kept.size());
    to += T1.translation() / double(kept.size());
    const double turn = std::remainder(heading(T1.linear()) - heading(T0.linear()), 2.0 * M_PI);
    s += std::sin(turn), c += std::cos(turn);
  }
  // Backed off towards where the goal posture's base is (over the seat), along the ground.
  Eigen::Vector3d towards_base = q.segment<3>(o + Entity::kBasePosition) - to;
  towards_base.z() = 0.0;
  if (towards_base.norm() > 1e-6) to += back_off * towards_base.normalized();
  const Eigen::Matrix3d R = Eigen::AngleAxisd(std::atan2(s, c), Eigen::Vector3d::UnitZ()).matrix();
  const Eigen::Vector3d p0 = problem.initial_configuration.segment<3>(o + Entity::kBasePosition);
  q.segment<3>(o + Entity::kBasePosition) = to + R * (p0 - from);
  const Eigen::Vector4d w = problem.initial_configuration.segment<4>(o + Entity::kBaseQuaternion);
  const Eigen::Quaterniond turned =
      Eigen::Quaterniond(R) * Eigen::Quaterniond(w[0], w[1], w[2], w[3]);
  q.segment<4>(o + Entity::kBaseQuaternion) << turned.w(), turned.x(), turned.y(), turned.z();
}

}  // namespace

std::optional<Approach> approach_configuration(const Problem& problem,
                                               const Eigen::VectorXd& q_goal, bool limbs_only,
                                               double back_off) {
  const Scene& scene = problem.scene;
  const System& system = scene.system;
  const std::vector<ModelData> at_goal = system_kinematics(system, q_goal);
  Approach approach{q_goal, {}, {}, back_off, limbs_only};
  bool any = false;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    if (entity.kind != EntityKind::FloatingRobot || entity.model->num_dofs() == 0) continue;
    const int j = system.offset(e) + entity.first_dof();
    const double change = (q_goal.segment(j, entity.model->num_dofs()) -
                           problem.initial_configuration.segment(j, entity.model->num_dofs()))
                              .cwiseAbs()
                              .maxCoeff();
    if (change <= kPostureChange) continue;
    std::vector<SurfaceRef> kept;
    for (const StanceContact& g : problem.goal_stance) {
      const std::optional<SurfaceRef> own = own_surface(g.contact, e);
      if (!own || !problem.in_initial_stance(g.contact)) continue;
      kept.push_back(*own);
      approach.kept.emplace_back(scene.surfaces.id(system, g.contact.s1),
                                 scene.surfaces.id(system, g.contact.s2));
    }
    if (kept.empty()) continue;
    carry_to_goal(problem, e, kept, at_goal, limbs_only, back_off, approach.q);
    approach.robots.push_back(e);
    any = true;
  }
  if (!any) return std::nullopt;
  return approach;
}

}  // namespace stanceplan
