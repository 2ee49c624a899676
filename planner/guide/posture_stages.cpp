#include "planner/guide/posture_stages.h"

#include <algorithm>
#include <optional>
#include <set>

#include "planner/solver/posture_solver.h"

namespace stanceplan {
namespace {

using Pair = std::pair<std::string, std::string>;

Pair pair_of(const Scene& scene, const Contact& c) {
  return {scene.surfaces.id(scene.system, c.s1), scene.surfaces.id(scene.system, c.s2)};
}

// The robot's own surface of a contact (the one on a floating robot), if any.
std::optional<SurfaceRef> robot_surface(const Scene& scene, const Contact& c) {
  for (SurfaceRef r : {c.s1, c.s2})
    if (scene.system.entity(r.entity).kind == EntityKind::FloatingRobot) return r;
  return std::nullopt;
}

// The links between a surface's link and its robot's root (the root excluded): its limb.
std::set<int> limb_of(const Scene& scene, SurfaceRef r) {
  const Model& model = *scene.system.entity(r.entity).model;
  std::set<int> out;
  for (int l = scene.surfaces.get(r).link; l > 0; l = model.links[size_t(l)].parent_link)
    out.insert(l);
  return out;
}

// Two contacts on one limb of one robot (a thigh and the sole below it): placed both, they pin
// the joints between them.
bool same_limb(const Scene& scene, const Contact& a, const Contact& b) {
  const std::optional<SurfaceRef> ra = robot_surface(scene, a), rb = robot_surface(scene, b);
  if (!ra || !rb || ra->entity != rb->entity) return false;
  const std::set<int> la = limb_of(scene, *ra), lb = limb_of(scene, *rb);
  return std::any_of(la.begin(), la.end(), [&](int l) { return lb.count(l) > 0; });
}

// Every contact fixed at its placement in q (E10-E13).
std::vector<StanceContact> placed(const Scene& scene, const std::vector<StanceContact>& contacts,
                                  const Eigen::VectorXd& q) {
  std::vector<StanceContact> out = contacts;
  for (StanceContact& c : out) c.placement = measure_placement(scene, c.contact, q);
  return out;
}

// One IK-statics solve of a stance, every contact loaded (E16), from q_init towards q_ref (E21).
std::optional<Eigen::VectorXd> solve(const Problem& problem, const std::vector<StanceContact>& s,
                                     const Eigen::VectorXd& q_init, const Eigen::VectorXd& q_ref,
                                     int* solves) {
  PostureRequest request = problem.loaded_request(s, q_init);
  request.q_ref = q_ref;
  const PostureSolver solver(problem.scene, problem.solver);
  const PostureResult r = solver.solve(request);
  if (solves != nullptr) ++*solves;
  // A stop at the iteration limit with every constraint within tolerance is a posture of the
  // stance all the same (contacts, balance, collisions hold): only its optimality is unproven, and
  // a milestone needs none (the crouch from the seated posture ends so).
  const bool feasible = r.status == PostureStatus::Solved ||
                        (r.status == PostureStatus::IterationLimit && !r.residuals.empty() &&
                         r.worst_family(problem.solver.tolerance).empty());
  if (!feasible) return std::nullopt;
  return r.q;
}

std::vector<Pair> pairs_of(const Scene& scene, const std::vector<StanceContact>& contacts) {
  std::vector<Pair> out;
  for (const StanceContact& c : contacts) out.push_back(pair_of(scene, c.contact));
  return out;
}

// The goal posture with the limbs that hold only contacts offered last (the forearms laid on the
// desk) back in their initial joints: the stages before those contacts reach for nothing (arms
// held out over the desk hit it while the robot still stands at its edge).
Eigen::VectorXd without_last_reach(const Problem& problem, const Eigen::VectorXd& q_goal,
                                   const std::vector<StanceContact>& last,
                                   const std::vector<StanceContact>& others) {
  const Scene& scene = problem.scene;
  const System& system = scene.system;
  Eigen::VectorXd q = q_goal;
  std::set<std::pair<int, int>> held;  // (entity, link) on the limbs of the other contacts
  for (const StanceContact& c : others)
    if (const auto r = robot_surface(scene, c.contact))
      for (int l : limb_of(scene, *r)) held.insert({r->entity, l});
  for (const StanceContact& c : last) {
    const std::optional<SurfaceRef> r = robot_surface(scene, c.contact);
    if (!r) continue;
    const Entity& entity = system.entity(r->entity);
    const Model& model = *entity.model;
    for (int l : limb_of(scene, *r)) {
      const int j = model.links[size_t(l)].parent_joint;
      if (held.count({r->entity, l}) > 0 || j < 0 || model.joints[size_t(j)].dof < 0) continue;
      const int i = system.offset(r->entity) + entity.first_dof() + model.joints[size_t(j)].dof;
      q[i] = problem.initial_configuration[i];
    }
  }
  return q;
}

}  // namespace

std::vector<PostureStage> posture_stages(const Problem& problem, const Eigen::VectorXd& q_goal,
                                         const ContactPhases& phases, int* solves) {
  const Scene& scene = problem.scene;
  const std::vector<StanceContact>& goal = problem.goal_stance;
  if (phases.shares.size() != goal.size()) return {};
  // The goal's contacts in three groups: kept from the initial stance, new ones that carry
  // weight (by decreasing share: the heaviest lands first), and those offered last.
  std::vector<StanceContact> kept, heavy, last;
  std::vector<size_t> order(goal.size());
  for (size_t c = 0; c < goal.size(); ++c) order[c] = c;
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return phases.shares[a] > phases.shares[b]; });
  for (size_t c : order) {
    const bool is_last = std::find(phases.last.begin(), phases.last.end(),
                                   pair_of(scene, goal[c].contact)) != phases.last.end();
    (phases.initial[c] ? kept : is_last ? last : heavy).push_back(goal[c]);
  }
  if (kept.empty() || heavy.empty()) return {};
  // Crouch: on the kept contacts alone, as near the goal posture as balance allows, the
  // contacts where the solver puts them (under the centre of mass: a seated robot's feet stretched
  // under the desk are no place to get up or sit down from).
  std::vector<StanceContact> carrying = kept;
  carrying.insert(carrying.end(), heavy.begin(), heavy.end());
  const Eigen::VectorXd q_ref = without_last_reach(problem, q_goal, last, carrying);
  const std::optional<Eigen::VectorXd> q_crouch = solve(problem, kept, q_ref, q_ref, solves);
  if (!q_crouch) return {};
  // Seated: every contact where the solver puts it, from the crouch (whose feet are under the
  // body, not stretched under the desk) towards the goal posture.
  std::vector<StanceContact> seated = carrying;
  const std::optional<Eigen::VectorXd> q_seated = solve(problem, seated, *q_crouch, q_ref, solves);
  if (!q_seated) return {};
  seated = placed(scene, seated, *q_seated);
  std::vector<Pair> sitting = pairs_of(scene, seated);
  std::vector<PostureStage> stages{{"crouch", *q_crouch, pairs_of(scene, kept)}};
  // One limb free: the last heavy contact and the kept ones on its limb wait.
  if (heavy.size() >= 2) {
    std::vector<StanceContact> part;
    for (const StanceContact& c : seated) {
      const bool waits = c.contact.same_surfaces(heavy.back().contact) ||
                         same_limb(scene, c.contact, heavy.back().contact);
      if (!waits) part.push_back(c);
    }
    if (const auto q = solve(problem, part, *q_seated, *q_seated, solves))
      stages.push_back({"one limb free", *q, sitting});
  }
  stages.push_back({"seated", *q_seated, sitting});
  // Goal: the last contacts added to the seated placements, reaching towards the goal posture.
  if (!last.empty()) {
    std::vector<StanceContact> full = seated;
    full.insert(full.end(), last.begin(), last.end());
    if (const auto q = solve(problem, full, *q_seated, q_goal, solves))
      stages.push_back({"goal", *q, {}});
    else
      stages.push_back({"goal", q_goal, {}});
  }
  return stages;
}

}  // namespace stanceplan
