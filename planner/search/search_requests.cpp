// Candidate generation and solver requests (search_run.h): the candidates of an expansion (Adj+
// and Adj- of the node's stance, candidates.h) and the request of each attempt: case 1 (add a
// contact, touched but unloaded, aimed by obj4) or case 2 (remove one: touched, unloaded), from
// the node's configuration, then, on retries, from the milestone or perturbed configurations.
#include <algorithm>
#include <cmath>
#include <random>

#include "planner/model/kinematics.h"
#include "planner/search/object_balance.h"
#include "planner/search/search_event_builders.h"
#include "planner/search/search_run.h"
#include "planner/search/step_target.h"
#include "planner/search/support_share.h"

namespace stanceplan {
namespace {

// Another initial guess for backtracking: the node's configuration with the joints moved by a
// deterministic pseudo-random amount (seeded by the node, the candidate and the attempt).
Eigen::VectorXd perturbed(const System& system, const Eigen::VectorXd& q, int node, int attempt,
                          size_t salt) {
  std::mt19937 rng(static_cast<unsigned>(node * 7919 + attempt * 104729 + salt));
  std::uniform_real_distribution<double> u(-0.15, 0.15);
  Eigen::VectorXd out = q;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    const Model& model = *entity.model;
    for (int k = 0; k < model.num_dofs(); ++k) {
      const Joint& joint = model.joints[model.dof_joints[k]];
      double& v = out[system.offset(e) + entity.first_dof() + k];
      v += u(rng);
      if (joint.has_position_limits) v = std::clamp(v, joint.lower, joint.upper);
    }
  }
  return out;
}

}  // namespace

// A milestone may state which contacts are offered while it is the target (a phase of the task:
// soles only while walking, thighs once sitting down).
SearchOptions StanceSearch::Run::options_for_milestone(int m) const {
  SearchOptions o = options_;
  const auto& phases = problem_.milestone_contact_pairs;
  if (m < int(phases.size()) && !phases[size_t(m)].empty()) o.contact_pairs = phases[size_t(m)];
  return o;
}

std::optional<std::vector<StanceSearch::Attempt>> StanceSearch::Run::expand(int n) {
  ++result_.nodes_expanded;
  expanded_for_.resize(tree_.size(), -1);
  expanded_for_[size_t(n)] = t_;
  const SearchNode& node = tree_[size_t(n)];
  if (!search_.publish(expansion_event(node, t_, int(tree_.size())))) return std::nullopt;
  const auto data = system_kinematics(problem_.scene.system, node.q());
  std::vector<Candidate> candidates = enumerate_candidates(
      problem_.scene, data, node.stance(), goal_, options_for_milestone(t_), &angles_, &reach_);
  std::vector<double> shares(candidates.size(), 0.0);
  // The order matters only to lazy expansion; all at once, the batch keeps Algorithm 1's order.
  if (options_.order_candidates && options_.expansion_batch > 0) {
    const Eigen::VectorXd q_guide =
        guide_.size() > 0 ? guide_.posture_near(node.q(), t_) : node.q();
    shares =
        order_by_support_share(problem_.scene, system_kinematics(problem_.scene.system, q_guide),
                               candidates, options_.placement_tolerance);
  }
  pending_.resize(tree_.size());
  pending_[size_t(n)].clear();
  for (size_t i = 0; i < candidates.size(); ++i) {
    const Candidate& c = candidates[i];
    if (removal_reaches_a_node(node, c)) continue;
    // Aimed at a node's placement, leaving a held object unbalanced, or failed from the same
    // situation before: solved only when backtracking (addition_aims_at_a_node, object_balance.h,
    // failure_memo.h).
    const bool deferred =
        (options_.defer_predicted_loops && addition_aims_at_a_node(node, c)) ||
        (options_.defer_unbalanced_removals && !c.add &&
         !objects_balance_without(problem_.scene, data, node.stance(), c.contact,
                                  solver_.options().friction, solver_.options().cone_generators)) ||
        (options_.defer_repeated_failures &&
         failures_.seen(problem_.scene, data, node.q(), node.stance(), c));
    if (deferred)
      retries_.push_back({n, c, 0, shares[i]});
    else
      pending_[size_t(n)].push_back({n, c, 0, shares[i]});
  }
  return take_pending(n);
}

// The next batch of node n's pending candidates. A batch of one when the guide's posture realises
// the first (support share within options_.batch_margin) and every other is an addition at least
// that much further: the rest are deferred to backtracking (retries_, tried once the open list is
// empty) and n leaves the open list, so a stale n is not expanded anew for the next milestone with
// its unlikely candidates (a knee on the floor beside a sole about to step).
std::vector<StanceSearch::Attempt> StanceSearch::Run::take_pending(int n) {
  std::deque<Attempt>& pending = pending_[size_t(n)];
  if (pending.empty()) return {};
  if (solves_alone(pending)) {
    std::vector<Attempt> batch{pending.front()};
    retries_.insert(retries_.end(), pending.begin() + 1, pending.end());
    pending.clear();
    return batch;
  }
  const size_t count = options_.expansion_batch > 0
                           ? std::min(pending.size(), size_t(options_.expansion_batch))
                           : pending.size();
  // In order, but one addition per class of facets (same link, same partner surface) while
  // defer_repeated_failures is on: the others wait for its outcome (if it fails, they go to
  // backtracking: defer_other_facets).
  std::vector<Attempt> batch;
  std::deque<Attempt> rest;
  for (Attempt& a : pending) {
    const bool twin = options_.expansion_batch > 0 && options_.defer_repeated_failures &&
                      std::any_of(batch.begin(), batch.end(),
                                  [&](const Attempt& b) { return same_facets(a, b); });
    if (batch.size() < count && !twin)
      batch.push_back(std::move(a));
    else
      rest.push_back(std::move(a));
  }
  pending = std::move(rest);
  if (!pending.empty()) open_.push_back(n);
  return batch;
}

// Two additions of surfaces of one link on the same partner surface (two facets of the held
// cylinder on platform B).
bool StanceSearch::Run::same_facets(const Attempt& a, const Attempt& b) const {
  if (!a.candidate.add || !b.candidate.add) return false;
  const Contact& x = a.candidate.contact;
  const Contact& y = b.candidate.contact;
  const SurfaceSet& surfaces = problem_.scene.surfaces;
  return x.s2 == y.s2 && x.s1.entity == y.s1.entity &&
         surfaces.get(x.s1).link == surfaces.get(y.s1).link;
}

bool StanceSearch::Run::solves_alone(const std::deque<Attempt>& pending) const {
  const Attempt& first = pending.front();
  const double margin = options_.batch_margin;
  if (options_.expansion_batch <= 0 || margin < 0.0 || !first.candidate.add || first.share > margin)
    return false;
  return std::all_of(pending.begin() + 1, pending.end(), [&](const Attempt& a) {
    return a.candidate.add && a.share > first.share + margin;
  });
}

StanceSearch::Run::AdditionAim StanceSearch::Run::addition_aim(const SearchNode& node,
                                                               const Contact& added,
                                                               int attempt) const {
  const Scene& scene = problem_.scene;
  const Eigen::VectorXd& q_ref = guide_.size() > 0 ? guide_.milestone(t_) : node.q();
  AdditionAim out;
  // obj4 pulls the new contact towards its placement in the targeted milestone; a retry aims at a
  // point nearer the current one (a shorter step); never across another contact.
  out.now = measure_placement(scene, added, node.q());
  const Placement aim = measure_placement(scene, added, q_ref);
  out.target = step_target(scene, node.stance(), node.placements, added, out.now, aim,
                           std::pow(0.5, attempt));
  // Heading for the goal (the last milestone), a goal contact with a stated placement is first
  // tried exactly there; a retry lets the solver choose.
  for (const StanceContact& g : problem_.goal_stance)
    if (g.placement && g.contact.same_surfaces(added) && attempt == 0 && t_ + 1 >= guide_.size())
      out.placement = g.placement;
  return out;
}

PostureRequest StanceSearch::Run::request_for(const Attempt& a, size_t index) const {
  const Scene& scene = problem_.scene;
  const SearchNode& node = tree_[size_t(a.node)];
  PostureRequest r;
  for (size_t k = 0; k < node.stance().contacts().size(); ++k)
    r.contacts.push_back(
        {node.stance().contacts()[k], true, node.placements[k], std::nullopt, {}, {}});
  const Eigen::VectorXd& q_ref = guide_.size() > 0 ? guide_.milestone(t_) : node.q();
  if (a.candidate.add) {
    ContactTask added{a.candidate.contact, false, std::nullopt, std::nullopt, {}, {}};
    const AdditionAim aim = addition_aim(node, a.candidate.contact, a.attempt);
    added.placement_target = aim.target;
    added.placement = aim.placement;
    r.contacts.push_back(added);
  } else {
    for (ContactTask& task : r.contacts)
      if (task.contact.same_surfaces(a.candidate.contact)) task.loaded = false;
  }
  // Initial guesses: the node's configuration; on the first retry the targeted milestone (often
  // in a better basin, e.g. sitting down); then perturbations of the node's configuration.
  r.q_init = a.attempt == 0   ? node.q()
             : a.attempt == 1 ? q_ref
                              : perturbed(scene.system, node.q(), a.node, a.attempt, index);
  r.q_ref = q_ref;
  r.progress_budget = options_.progress_budget;
  return r;
}

}  // namespace stanceplan
