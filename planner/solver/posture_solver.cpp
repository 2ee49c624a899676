#include "planner/solver/posture_solver.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <optional>
#include <span>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

#include "planner/collision/signed_distance.h"
#include "planner/model/kinematics.h"
#include "planner/solver/blocks/blocks.h"
#include "planner/solver/force_balance.h"
#include "planner/solver/ipopt_adapter.h"
#include "planner/solver/pinned_pairs.h"
#include "planner/solver/posture_nlp.h"

namespace stanceplan {
namespace {

// "" when the guess can be used; else why not: a non-finite entry of q_init or q_ref, or a zero
// base quaternion (kinematics divide by its norm: every pose would be NaN, which the collision
// library asserts on).
std::string unusable_guess(const System& system, const PostureRequest& request) {
  for (const auto& [name, q] :
       {std::pair{"q_init", &request.q_init}, std::pair{"q_ref", &request.q_ref}})
    for (int i = 0; i < q->size(); ++i)
      if (!std::isfinite((*q)[i]))
        return "the initial guess is not finite (" + std::string(name) + "[" + std::to_string(i) +
               "] = " + std::to_string((*q)[i]) + ")";
  for (int e = 0; e < system.num_entities(); ++e)
    if (system.entity(e).floating() &&
        request.q_init.segment<4>(system.offset(e) + Entity::kBaseQuaternion).norm() < 1e-9)
      return "the initial guess has a zero base quaternion (entity \"" + system.entity(e).name +
             "\")";
  return "";
}

// Signed distance of every candidate pair that is not excluded (+inf for excluded ones).
std::vector<double> pair_distances(const Scene& scene, const Eigen::VectorXd& q,
                                   const std::vector<bool>& excluded, double cutoff) {
  const CollisionModel& model = *scene.collision;
  const std::vector<ModelData> data = system_kinematics(scene.system, q);
  CollisionData work(scene.system, model);
  work.update(model, data);
  std::vector<double> d(model.pairs().size(), INFINITY);
  for (size_t p = 0; p < d.size(); ++p) {
    if (excluded[p]) continue;
    if (distance_lower_bound(model, data, int(p)) >= cutoff) continue;  // certainly far
    d[p] = signed_distance(model, work, int(p)).distance;
  }
  return d;
}

// " (closest pair: robot/l_knee_p_link / env/chair at -0.004 m)" for the pair nearest to
// violating the margin at q, or "" when none is closer than the margin.
std::string closest_pair(const Scene& scene, const Eigen::VectorXd& q,
                         const std::vector<bool>& excluded, double margin) {
  const std::vector<double> d = pair_distances(scene, q, excluded, margin);
  const auto worst = std::min_element(d.begin(), d.end());
  if (worst == d.end() || !(*worst < margin)) return "";
  const CollisionModel& model = *scene.collision;
  const CollisionPair& pair = model.pairs()[size_t(worst - d.begin())];
  auto name = [&](int l) {
    const CollisionLink& link = model.links()[size_t(l)];
    const Entity& e = scene.system.entity(link.entity);
    return e.name + "/" + e.model->links[size_t(link.link)].name;
  };
  std::ostringstream out;
  out << " (closest pair: " << name(pair.a) << " / " << name(pair.b) << " at " << std::fixed
      << std::setprecision(3) << *worst << " m)";
  return out.str();
}

// E20's bound for a pair: the margin, except that a pair touching or nearly so at the initial
// guess need not move apart further than it is: a foot just lifted off the floor may stay touching
// it (d >= 0), which keeps the guess feasible where the distance between parallel faces is least
// smooth. A pair penetrating at the guess (a bad guess) must reach the full margin.
double collision_bound(double distance_at_guess, double margin) {
  return distance_at_guess >= -1e-6 ? std::min(margin, std::max(0.0, distance_at_guess)) : margin;
}

// Per candidate pair: whether it joins the links of a contact the request is approaching
// (PostureRequest::approaching), whose E20 bound is 0 instead of collision_bound's.
std::vector<bool> approaching_pairs(const Scene& scene, const PostureRequest& request) {
  std::vector<bool> out(scene.collision ? scene.collision->pairs().size() : 0, false);
  if (!scene.collision) return out;
  for (const Contact& c : request.approaching) {
    const int p = scene.collision->find_pair(c.s1.entity, scene.surfaces.get(c.s1).link,
                                             c.s2.entity, scene.surfaces.get(c.s2).link);
    if (p >= 0) out[size_t(p)] = true;
  }
  return out;
}

// The pinned pairs (pinned_pairs.h) at the link poses of `data` against their E20 bounds: an
// Infeasible result naming the pair furthest below its bound, or nullopt when every one keeps it.
// `guess`: the same pairs at the initial guess (their E20 bounds).
std::optional<PostureResult> pinned_pair_collision(const Scene& scene,
                                                   const PostureRequest& request,
                                                   std::span<const ModelData> data,
                                                   const std::vector<PinnedPairDistance>& guess,
                                                   double margin) {
  const std::vector<PinnedPairDistance> now = pinned_pair_distances(scene, request, data);
  double worst = 1e-4;  // the tolerance of the collision active set's own check
  int worst_index = -1;
  for (size_t i = 0; i < now.size(); ++i) {
    const double shortfall = collision_bound(guess[i].distance, margin) - now[i].distance;
    if (shortfall > worst) worst = shortfall, worst_index = int(i);
  }
  if (worst_index < 0) return std::nullopt;
  const PinnedPairDistance& d = now[size_t(worst_index)];
  const CollisionPair& pair = scene.collision->pairs()[size_t(d.pair)];
  auto pinned_by = [&](int contact) {
    if (contact < 0) return std::string("never moves");
    const Contact& c = request.contacts[size_t(contact)].contact;
    return "pinned by contact " + scene.surfaces.id(scene.system, c.s1) + " on " +
           scene.surfaces.id(scene.system, c.s2);
  };
  std::ostringstream out;
  out << "collision: " << collision_link_name(scene, pair.a) << " (" << pinned_by(d.contact_a)
      << ") and " << collision_link_name(scene, pair.b) << " (" << pinned_by(d.contact_b)
      << ") are " << std::fixed << std::setprecision(4)
      << (d.distance < 0 ? -d.distance : d.distance)
      << (d.distance < 0 ? " m into each other" : " m apart") << ", at least " << d.distance + worst
      << " m apart expected; fixed placements leave no freedom to part them";
  PostureResult result;
  result.status = PostureStatus::Infeasible;
  result.message = out.str();
  result.residuals["collision"] = worst;
  result.blocking_family = "collision";
  return result;
}

void normalise_quaternions(const System& system, Eigen::VectorXd& q) {
  for (int e = 0; e < system.num_entities(); ++e)
    if (system.entity(e).floating()) {
      auto quat = q.segment<4>(system.offset(e) + Entity::kBaseQuaternion);
      quat /= quat.norm();
    }
}

void record_residuals(PostureNlp& nlp, const Eigen::VectorXd& x, PostureResult& result) {
  const int n = nlp.n(), m = nlp.m();
  Eigen::VectorXd g(m), gl(m), gu(m), xl(n), xu(n);
  nlp.constraints(x.data(), true, g.data());
  nlp.constraint_bounds(gl.data(), gu.data());
  nlp.variable_bounds(xl.data(), xu.data());
  for (size_t b = 0; b < nlp.blocks().size(); ++b) {
    const auto& block = nlp.blocks()[b];
    double& worst = result.residuals[block->family()];
    for (int r = 0; r < block->rows(); ++r) {
      const int i = nlp.block_first_row(int(b)) + r;
      const double violation = std::max({gl[i] - g[i], g[i] - gu[i], 0.0});
      if (violation <= worst) continue;
      worst = violation;
      if (block->contact() >= 0) result.residual_contacts[block->family()] = block->contact();
    }
  }
  double& limits = result.residuals["joint_limits"];
  for (int i = 0; i < nlp.layout().nq; ++i)
    limits = std::max({limits, xl[i] - x[i], x[i] - xu[i], 0.0});
  double& friction = result.residuals["friction"];
  for (int i = nlp.layout().nq; i < n; ++i) friction = std::max({friction, xl[i] - x[i], 0.0});
}

void record_physics(PostureNlp& nlp, const PostureRequest& request, PostureResult& result) {
  NlpState& state = nlp.state();
  state.ensure_torques();
  for (size_t t = 0; t < request.contacts.size(); ++t) {
    const ContactFrames& f = state.frames[t];
    const Eigen::Vector3d d = f.O1 - f.O2;
    // A point surface has no orientation in s2's plane: its theta is 0 (surface.h).
    const bool point = state.scene.surfaces.get(request.contacts[t].contact.s1).is_point();
    result.placements.push_back(
        {d.dot(f.x2), d.dot(f.y2), point ? 0.0 : std::atan2(f.x1.dot(f.y2), f.x1.dot(f.x2))});
    if (nlp.layout().force_block_of_task[t] < 0) continue;
    // Where each force acts: s1's vertex, or for a point contact one radius below the centre, on
    // s2's plane (E17-E18 take it there; plan files and certify read this point).
    for (size_t j = 0; j < f.p.size(); ++j)
      result.forces.push_back({int(t), int(j), f.p[j] - state.constants[t].radius * f.z2, f.f[j]});
  }
  result.torques = state.tau;
}

// What a round's solution exceeds among the rows left out of its program.
struct RoundExcess {
  double torque = 0.0;   // worst |tau| / effort - 1 over every limited joint
  double polygon = 0.0;  // worst vertex distance outside an edge over every polygon row
  std::vector<Eigen::VectorXd> polygon_margins;  // per contact, per polygon row
};
RoundExcess record_round(PostureNlp& nlp, const Eigen::VectorXd& x, const PostureRequest& request,
                         const SolverOptions& options, PostureResult& result);

// Calls visit(entity, dof, |tau| / effort) for every dof of a robot with an effort limit (the
// rows of TorqueLimitBlock).
template <class Visit>
void for_each_limited_joint(const System& system, const std::vector<Eigen::VectorXd>& tau,
                            Visit visit) {
  for (int e = 0; e < system.num_entities(); ++e) {
    const Model& model = *system.entity(e).model;
    if (system.entity(e).kind == EntityKind::Object || size_t(e) >= tau.size() ||
        tau[size_t(e)].size() == 0)
      continue;
    for (int k = 0; k < model.num_dofs(); ++k) {
      const double effort = model.joints[model.dof_joints[k]].effort;
      if (effort > 0.0) visit(e, k, std::abs(tau[size_t(e)][k]) / effort);
    }
  }
}

// Per entity, the dofs with an effort limit whose |tau| / effort is at least `fraction`.
std::vector<std::vector<int>> loaded_joints(const System& system,
                                            const std::vector<Eigen::VectorXd>& tau,
                                            double fraction) {
  std::vector<std::vector<int>> dofs(size_t(system.num_entities()));
  for_each_limited_joint(system, tau, [&](int e, int k, double ratio) {
    if (ratio >= fraction) dofs[size_t(e)].push_back(k);
  });
  return dofs;
}

// Per contact, the margin of every row of its PolygonBlock (vertex inside edge, m) at the state's
// x; empty for a contact with a fixed placement (no such rows).
std::vector<Eigen::VectorXd> polygon_margins(NlpState& state) {
  std::vector<Eigen::VectorXd> margins(state.request.contacts.size());
  for (size_t t = 0; t < margins.size(); ++t) {
    if (state.request.contacts[t].placement) continue;
    const PolygonBlock block(state, int(t));
    margins[t].resize(block.rows());
    block.evaluate(state, margins[t]);
  }
  return margins;
}

// Per contact, the polygon rows whose margin is below `distance`: for loaded contacts only; the
// contact that case 1 adds keeps every row (its placement is what the solve chooses, and the
// barrier of its far edges keeps that choice off them: measured with robustness_bench, the desk's
// eight searches took 917 solver calls with its rows left out too, 677 without).
std::vector<std::vector<int>> rows_below(const PostureRequest& request,
                                         const std::vector<Eigen::VectorXd>& margins,
                                         double distance) {
  std::vector<std::vector<int>> rows(margins.size());
  for (size_t t = 0; t < margins.size(); ++t)
    for (int r = 0; r < margins[t].size(); ++r)
      if (margins[t][r] < distance || !request.contacts[t].loaded) rows[t].push_back(r);
  return rows;
}

// Where the program starts (q_init and the force guesses): the torques and the polygon margins,
// from which the torque and polygon active sets are chosen.
struct StartingPoint {
  std::vector<Eigen::VectorXd> torques;
  std::vector<Eigen::VectorXd> polygon_margins;
};

// Without force guesses, the request gets as guesses the forces that balance every body at
// q_init at least cost (force_balance.h), when there are such forces. Returns where the program
// starts.
StartingPoint prepare_start(const Scene& scene, PostureRequest& request,
                            const SolverOptions& options) {
  const NlpLayout layout(scene, request, options);
  NlpState state(scene, request, options, layout);
  Eigen::VectorXd x0 = make_starting_point(state);
  const bool guessed =
      std::any_of(request.contacts.begin(), request.contacts.end(),
                  [](const ContactTask& task) { return !task.force_guess_W.empty(); });
  if (options.balance_starting_forces && !guessed && balance_starting_forces(state, x0).balanced) {
    for (const ForceBlock& block : layout.forces)
      request.contacts[size_t(block.task)].force_guess_W = state.frames[size_t(block.task)].f;
  }
  state.ensure_torque_values();
  return {state.tau, polygon_margins(state)};
}

// Adds to `active` every index in `wanted` it lacks (per entity or contact); true when one was
// added.
bool merge_indices(std::vector<std::vector<int>>& active,
                   const std::vector<std::vector<int>>& wanted) {
  bool added = false;
  for (size_t e = 0; e < active.size(); ++e)
    for (int k : wanted[e])
      if (std::find(active[e].begin(), active[e].end(), k) == active[e].end()) {
        active[e].push_back(k);
        added = true;
      }
  for (std::vector<int>& indices : active) std::sort(indices.begin(), indices.end());
  return added;
}

// Worst |tau| / effort - 1 over every limited dof (0 when all are within their limits).
double worst_torque_excess(const System& system, const std::vector<Eigen::VectorXd>& tau) {
  double worst = 0.0;
  for_each_limited_joint(system, tau,
                         [&](int, int, double ratio) { worst = std::max(worst, ratio - 1.0); });
  return worst;
}

// The forces of a result as the next round's force guesses.
void guess_forces_from(const PostureResult& result, PostureRequest& request) {
  for (const VertexForce& f : result.forces) {
    std::vector<Eigen::Vector3d>& guess = request.contacts[size_t(f.contact)].force_guess_W;
    if (guess.size() <= size_t(f.vertex))
      guess.resize(size_t(f.vertex) + 1, Eigen::Vector3d::Zero());
    guess[size_t(f.vertex)] = f.force_W;
  }
}

// Pairs outside the active set whose distance d fell below their bound join it (sorted later);
// returns the worst penetration over every pair.
double grow_collision_set(const std::vector<double>& d, const std::vector<double>& bound,
                          std::vector<int>& active) {
  double worst = 0.0;
  for (size_t p = 0; p < d.size(); ++p) {
    if (d[p] < bound[p] - 1e-4 && std::find(active.begin(), active.end(), int(p)) == active.end())
      active.push_back(int(p));
    if (d[p] < 0) worst = std::max(worst, -d[p]);
  }
  return worst;
}

// Why a solve whose active sets still grow after the last allowed round is infeasible.
std::string rounds_exhausted(bool collisions_grew, bool torques_grew, int rounds) {
  return std::string(collisions_grew ? "collision: pairs still closer than the margin"
                     : torques_grew  ? "torque_limits: joints still beyond their effort"
                                     : "polygon: vertices still outside their polygon") +
         " after " + std::to_string(rounds) + " active-set rounds";
}

// Appends the family to blame at the final iterate to a failed result's message, with its residual
// against the constraint tolerance (a stop on the iteration limit may leave every constraint
// within it: then the dual or complementarity test is what failed, and the message says so), the
// contact for a family of one contact, and, when it is collision (and `excluded` is given:
// collisions enforced), the pair nearest to violating the margin.
void name_worst_family(const Scene& scene, const PostureRequest& request,
                       const std::vector<bool>* excluded, const SolverOptions& options,
                       PostureResult& result) {
  if (result.residuals.empty()) return;
  // Blamed: the worst in its own unit among the families beyond the tolerance, else overall.
  const std::string beyond = result.worst_family(options.tolerance);
  const bool violated = !beyond.empty();
  const std::string family = violated ? beyond : result.worst_family();
  char figures[96];
  std::snprintf(figures, sizeof(figures), " (%.1e, tolerance %.0e)", result.residuals.at(family),
                options.tolerance);
  if (!violated) {
    result.message += "; every constraint family within tolerance at the final iterate, largest " +
                      family + figures + ": the optimality or complementarity test failed";
    return;
  }
  result.message += "; worst violated family: " + family;
  if (const auto it = result.residual_contacts.find(family);
      it != result.residual_contacts.end() && it->second < int(request.contacts.size())) {
    const Contact& c = request.contacts[size_t(it->second)].contact;
    result.message += " at contact " + scene.surfaces.id(scene.system, c.s1) + " on " +
                      scene.surfaces.id(scene.system, c.s2);
  }
  result.message += figures;
  if (excluded && family == "collision" && result.q.size() == scene.system.nq())
    result.message += closest_pair(scene, result.q, *excluded, options.collision_margin);
}

// The round's solution into `result`: configuration, forces, placements, torques and the residual
// of every family, the torque and polygon rows left out of the program included.
RoundExcess record_round(PostureNlp& nlp, const Eigen::VectorXd& x, const PostureRequest& request,
                         const SolverOptions& options, PostureResult& result) {
  const System& system = nlp.state().scene.system;
  result.residuals.clear();
  result.residual_contacts.clear();
  result.forces.clear();
  result.placements.clear();
  record_residuals(nlp, x, result);
  result.q = x.head(system.nq());
  nlp.state().set_x(x.data());
  record_physics(nlp, request, result);
  RoundExcess excess;
  excess.torque = worst_torque_excess(system, result.torques);
  if (options.enforce_torque_limits)  // every limited joint, the rows left out included
    result.residuals["torque_limits"] = std::max(result.residuals["torque_limits"], excess.torque);
  excess.polygon_margins = polygon_margins(nlp.state());
  bool has_polygon_rows = false;  // every polygon row, the ones left out included
  int worst_polygon = -1;
  for (size_t t = 0; t < excess.polygon_margins.size(); ++t) {
    const Eigen::VectorXd& rows = excess.polygon_margins[t];
    if (rows.size() == 0) continue;
    has_polygon_rows = true;
    if (-rows.minCoeff() > excess.polygon) worst_polygon = int(t);
    excess.polygon = std::max(excess.polygon, -rows.minCoeff());
  }
  if (has_polygon_rows && excess.polygon > result.residuals["polygon"]) {
    result.residuals["polygon"] = excess.polygon;
    if (worst_polygon >= 0) result.residual_contacts["polygon"] = worst_polygon;
  }
  return excess;
}

}  // namespace

PostureSolver::PostureSolver(const Scene& scene, SolverOptions options)
    : scene_(scene), options_(std::move(options)) {
  if (options_.cone_generators < 3)
    throw std::invalid_argument("cone_generators must be >= 3, got " +
                                std::to_string(options_.cone_generators));
  if (!(options_.friction > 0.0))
    throw std::invalid_argument("friction must be > 0, got " + std::to_string(options_.friction));
}

void PostureSolver::validate(const PostureRequest& request) const {
  const System& system = scene_.system;
  if (request.q_init.size() != system.nq())
    throw std::invalid_argument("q_init has " + std::to_string(request.q_init.size()) +
                                " entries, the system has " + std::to_string(system.nq()));
  if (request.q_ref.size() != 0 && request.q_ref.size() != system.nq())
    throw std::invalid_argument("q_ref has " + std::to_string(request.q_ref.size()) +
                                " entries, the system has " + std::to_string(system.nq()));
  // A surface is the smaller side (s1) of at most one contact and then of nothing else; a larger
  // surface (s2, e.g. the floor) may support several contacts.
  const auto exists = [&](SurfaceRef s) {
    return s.entity >= 0 && s.entity < system.num_entities() && s.index >= 0 &&
           s.index < int(scene_.surfaces.of(s.entity).size());
  };
  for (const Contact& c : request.approaching)
    if (!exists(c.s1) || !exists(c.s2))
      throw std::invalid_argument("an approaching contact names a surface that does not exist");
  std::vector<SurfaceRef> smaller, larger;
  for (const ContactTask& task : request.contacts) {
    for (SurfaceRef s : {task.contact.s1, task.contact.s2})
      if (!exists(s)) throw std::invalid_argument("a contact names a surface that does not exist");
    const SurfaceRef r1 = task.contact.s1, r2 = task.contact.s2;
    const auto in = [](const std::vector<SurfaceRef>& list, SurfaceRef s) {
      return std::find(list.begin(), list.end(), s) != list.end();
    };
    if (in(smaller, r1) || in(larger, r1) || in(smaller, r2))
      throw std::invalid_argument(
          "surface " + scene_.surfaces.id(system, in(smaller, r2) ? r2 : r1) +
          " is in two contacts (a contact's smaller surface s1 is in no other)");
    smaller.push_back(r1);
    larger.push_back(r2);
    if (task.standoff != 0.0 && (task.loaded || !task.placement || !std::isfinite(task.standoff)))
      throw std::invalid_argument("contact " + scene_.surfaces.id(system, r1) +
                                  ": a standoff needs an unloaded contact with a fixed placement");
    const Surface& s1 = scene_.surfaces.get(task.contact.s1);
    const Surface& s2 = scene_.surfaces.get(task.contact.s2);
    if (task.contact.s1.entity == task.contact.s2.entity && s1.link == s2.link)
      throw std::invalid_argument("contact " + scene_.surfaces.id(system, task.contact.s1) + " - " +
                                  scene_.surfaces.id(system, task.contact.s2) +
                                  " joins two surfaces of one link");
    // Point surfaces (surface.h) are s1 only: the sphere touches s2's plane.
    if (s2.is_point())
      throw std::invalid_argument("contact " + scene_.surfaces.id(system, task.contact.s1) + " - " +
                                  scene_.surfaces.id(system, task.contact.s2) +
                                  ": a point surface can only be s1");
  }
}

std::vector<bool> PostureSolver::excluded_pairs(const PostureRequest& request) const {
  const std::vector<PairExclusion> why = pair_exclusions(scene_, request);
  std::vector<bool> excluded(why.size(), false);
  for (size_t p = 0; p < why.size(); ++p) excluded[p] = why[p] != PairExclusion::None;
  return excluded;
}

PostureResult PostureSolver::solve(const PostureRequest& request) const {
  return solve_with(request, options_);
}

PostureResult PostureSolver::solve(const PostureRequest& request,
                                   const std::atomic<bool>* cancel) const {
  SolverOptions options = options_;
  options.cancel = cancel;
  return solve_with(request, options);
}

PostureResult PostureSolver::solve_with(const PostureRequest& request,
                                        const SolverOptions& given) const {
  validate(request);
  // Cancelled before it starts: Ipopt never runs.
  if (given.cancel && given.cancel->load()) return PostureResult::numerical_failure("cancelled");
  SolverOptions options = given;
  if (request.progress_budget > 0) options.stall.budget = request.progress_budget;
  // An unusable guess (e.g. a NaN from a degenerate configuration upstream) is a failed candidate
  // with its reason, not a malformed request; Ipopt never sees it.
  if (std::string reason = unusable_guess(scene_.system, request); !reason.empty())
    return PostureResult::numerical_failure(std::move(reason));
  const bool collisions = scene_.collision && options.enforce_collisions;
  // Pinned pairs have no row in the program: their distance follows from the fixed placements
  // alone, so a stance that puts them into each other is infeasible before any solve.
  std::vector<PinnedPairDistance> pinned_at_guess;
  if (collisions && has_pinned_pair(scene_, request)) {
    std::vector<ModelData> data = system_kinematics(scene_.system, request.q_init);
    pinned_at_guess = pinned_pair_distances(scene_, request, data);
    place_pinned_links(scene_, request, data);
    if (auto failed =
            pinned_pair_collision(scene_, request, data, pinned_at_guess, options.collision_margin))
      return *failed;
  }
  PostureResult result = solve_once(request, options);
  // No NaN reaches a plan: a "solved" result with a non-finite number in it is a failure.
  if (const std::string part = result.non_finite_part();
      result.status == PostureStatus::Solved && !part.empty()) {
    result.status = PostureStatus::NumericalFailure;
    result.message = "non-finite " + part + " in the solution (" + result.message + ")";
  }
  // ... and checked again on the solution, where the placements hold to the solver's tolerance.
  if (result.status == PostureStatus::Solved && !pinned_at_guess.empty())
    if (auto failed =
            pinned_pair_collision(scene_, request, system_kinematics(scene_.system, result.q),
                                  pinned_at_guess, options.collision_margin)) {
      failed->q = result.q;
      failed->iterations = result.iterations;
      failed->time_ms = result.time_ms;
      return *failed;
    }
  if (result.status != PostureStatus::Solved && options.diagnose_infeasibility)
    diagnose(request, options, result);
  return result;
}

void PostureSolver::diagnose(const PostureRequest& request, const SolverOptions& options,
                             PostureResult& result) const {
  SolverOptions relaxed = options;
  relaxed.enforce_torque_limits = false;
  if (solve_once(request, relaxed).status == PostureStatus::Solved) {
    result.blocking_family = "torque_limits";
  } else if (scene_.collision) {
    relaxed = options;
    relaxed.enforce_collisions = false;
    if (solve_once(request, relaxed).status == PostureStatus::Solved)
      result.blocking_family = "collision";
  }
  if (!result.blocking_family.empty())
    result.message +=
        "; infeasible because of " + result.blocking_family + " (solved without them)";
}

PostureResult PostureSolver::solve_once(const PostureRequest& request_in,
                                        const SolverOptions& options) const {
  PostureRequest request = request_in;
  PostureResult result;
  const auto start = std::chrono::steady_clock::now();
  std::vector<int> active;
  std::vector<double> initial_distance;  // per candidate pair, at the initial guess
  std::vector<bool> excluded = excluded_pairs(request);
  const bool collisions = scene_.collision && options.enforce_collisions;
  if (collisions) {
    initial_distance =
        pair_distances(scene_, request.q_init, excluded, options.collision_active_distance);
    for (size_t p = 0; p < initial_distance.size(); ++p)
      if (initial_distance[p] < options.collision_active_distance) active.push_back(int(p));
  }
  // E20 with the margin (collision_bound); 0 for a pair the request approaches.
  const std::vector<bool> approaching = approaching_pairs(scene_, request);
  auto bound_of = [&](int p) {
    return approaching[size_t(p)] ? 0.0
                                  : collision_bound(initial_distance[p], options.collision_margin);
  };
  auto bounds_of = [&](const std::vector<int>& pairs) {
    std::vector<double> bounds;
    for (int p : pairs) bounds.push_back(bound_of(p));
    return bounds;
  };
  auto bounds_of_all = [&] {
    std::vector<double> bounds(initial_distance.size());
    for (size_t p = 0; p < bounds.size(); ++p) bounds[p] = bound_of(int(p));
    return bounds;
  };
  // E19 rows far from their limits at the start are left out until a solution exceeds them, and
  // so are the polygon rows of vertices far inside their edges until one crosses.
  const StartingPoint start_point = prepare_start(scene_, request, options);
  const bool torque_set = options.enforce_torque_limits && options.torque_active_fraction > 0.0;
  std::vector<std::vector<int>> torque_dofs;
  if (torque_set)
    torque_dofs = loaded_joints(scene_.system, start_point.torques, options.torque_active_fraction);
  std::vector<std::vector<int>> polygon_rows =
      rows_below(request, start_point.polygon_margins, options.polygon_active_distance);
  for (int round = 0;; ++round) {
    PostureNlp nlp(scene_, request, options, active, bounds_of(active), hessian_cache_.get(),
                   torque_set ? &torque_dofs : nullptr, &polygon_rows);
    const IpoptRun run = run_ipopt(nlp, options);
    result.iterations += run.iterations;
    result.status = run.status;
    result.message = run.message;
    result.objective = run.objective;
    if (run.x.size() != nlp.n()) break;
    const RoundExcess excess = record_round(nlp, run.x, request, options, result);
    const double torque_excess = excess.torque, polygon_excess = excess.polygon;
    const std::vector<Eigen::VectorXd>& margins = excess.polygon_margins;
    if (run.status != PostureStatus::Solved) break;
    // Pairs outside the active set may have come closer than the margin: add them.
    const size_t before = active.size();
    if (collisions) {
      // The active pairs are rows of the program: their E20 residuals are recorded already.
      std::vector<bool> unchecked = excluded;
      for (int p : active) unchecked[size_t(p)] = true;
      const double worst =
          grow_collision_set(pair_distances(scene_, result.q, unchecked, options.collision_margin),
                             bounds_of_all(), active);
      result.residuals["collision"] = std::max(result.residuals["collision"], worst);
    }
    // Torques beyond a limit left out: add those rows, and the ones near their limits.
    const bool torques_grew =
        torque_set && torque_excess > options.tolerance &&
        merge_indices(torque_dofs, loaded_joints(scene_.system, result.torques, 0.9));
    // Vertices outside an edge left out: add those rows, and the ones near their edges.
    const bool polygons_grew =
        polygon_excess > options.tolerance &&
        merge_indices(polygon_rows, rows_below(request, margins, options.polygon_active_distance));
    if (active.size() == before && !torques_grew && !polygons_grew) break;
    if (round + 1 >= options.max_active_set_rounds) {
      result.status = PostureStatus::Infeasible;
      result.message = rounds_exhausted(active.size() != before, torques_grew, round + 1);
      break;
    }
    std::sort(active.begin(), active.end());
    request.q_init = result.q;
    guess_forces_from(result, request);
  }
  if (result.q.size() == scene_.system.nq()) normalise_quaternions(scene_.system, result.q);
  if (result.status != PostureStatus::Solved)
    name_worst_family(scene_, request, collisions ? &excluded : nullptr, options, result);
  result.time_ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return result;
}

Placement measure_placement(const Scene& scene, const Contact& contact, const Eigen::VectorXd& q) {
  const System& system = scene.system;
  const Surface& s1 = scene.surfaces.get(contact.s1);
  const Surface& s2 = scene.surfaces.get(contact.s2);
  auto frame = [&](SurfaceRef ref, const Surface& s) {
    const Entity& e = system.entity(ref.entity);
    ModelData data(e);
    forward_kinematics(e, q.segment(system.offset(ref.entity), e.nq()), data);
    return Eigen::Isometry3d(data.T_WL[s.link] * s.T_LS);
  };
  const Eigen::Isometry3d T1 = frame(contact.s1, s1), T2 = frame(contact.s2, s2);
  const Eigen::Vector3d d = T1.translation() - T2.translation();
  const Eigen::Vector3d x1 = T1.linear().col(0);
  return {d.dot(T2.linear().col(0)), d.dot(T2.linear().col(1)),
          s1.is_point() ? 0.0  // a point has no orientation in s2's plane
                        : std::atan2(x1.dot(T2.linear().col(1)), x1.dot(T2.linear().col(0)))};
}

}  // namespace stanceplan
