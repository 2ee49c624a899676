#include "planner/guide/contact_phases.h"

#include <algorithm>
#include <cmath>

namespace stanceplan {

ContactPhases order_goal_contacts(const Problem& problem, const PostureResult& goal) {
  const Scene& scene = problem.scene;
  const size_t n = problem.goal_stance.size();
  ContactPhases phases;
  phases.shares.assign(n, 0.0);
  phases.initial.assign(n, false);
  if (scene.gravity.norm() == 0.0) return phases;  // nothing to carry: no order
  // E16: the weight is balanced by the contact forces; each contact's part of it is the vertical
  // component of the forces at its vertices (|.|: the force on s1, whichever side carries).
  const Eigen::Vector3d up_W = -scene.gravity.normalized();
  std::vector<double> lift(n, 0.0);
  for (const VertexForce& f : goal.forces)
    if (f.contact >= 0 && size_t(f.contact) < n) lift[size_t(f.contact)] += f.force_W.dot(up_W);
  double total = 0.0;
  for (double& l : lift) total += (l = std::abs(l));
  if (total <= 0.0) return phases;
  double largest_new = 0.0;
  for (size_t c = 0; c < n; ++c) {
    phases.shares[c] = lift[c] / total;
    phases.initial[c] = problem.in_initial_stance(problem.goal_stance[c].contact);
    if (!phases.initial[c]) largest_new = std::max(largest_new, phases.shares[c]);
  }
  for (size_t c = 0; c < n; ++c) {
    if (phases.initial[c] || phases.shares[c] >= ContactPhases::kSteadyingShare * largest_new)
      continue;
    const Contact& k = problem.goal_stance[c].contact;
    phases.last.emplace_back(scene.surfaces.id(scene.system, k.s1),
                             scene.surfaces.id(scene.system, k.s2));
  }
  return phases;
}

}  // namespace stanceplan
