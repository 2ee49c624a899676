#include "planner/search/stance_search.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <random>
#include <thread>

#include "planner/io/plan_step.h"
#include "planner/model/kinematics.h"
#include "planner/search/candidates.h"
#include "planner/search/plan_path.h"
#include "planner/search/stance_checks.h"
#include "planner/search/step_target.h"
#include "planner/solver/posture_solver.h"
#include "planner/solver/solver_pool.h"

namespace stanceplan {

const char* to_string(PlanStatus status) {
  switch (status) {
    case PlanStatus::Found: return "found";
    case PlanStatus::Exhausted: return "exhausted";
    case PlanStatus::NodeBudget: return "node budget";
    case PlanStatus::TimeBudget: return "time budget";
    case PlanStatus::Cancelled: return "cancelled";
    case PlanStatus::InitialInfeasible: return "initial stance infeasible";
  }
  return "?";
}

// One candidate solve: a (node, candidate) pair and which attempt it is (0, then backtracking).
struct StanceSearch::Attempt {
  int node = -1;
  Candidate candidate;
  int attempt = 0;
};

namespace {

using Clock = std::chrono::steady_clock;


int stance_difference(const Stance& a, const Stance& b) {
  int d = 0;
  for (const Contact& c : a.contacts()) d += b.find(c) < 0;
  for (const Contact& c : b.contacts()) d += a.find(c) < 0;
  return d;
}

// Another initial guess for backtracking: the node's configuration with the joints moved by a
// deterministic pseudo-random amount (seeded by the node, the candidate and the attempt).
Eigen::VectorXd perturbed(const System& system, const Eigen::VectorXd& q, int node, int attempt, size_t salt) {
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

// Removing the contact that made a node gives back its parent's stance at the parent's placements,
// which loop avoidance would reject after the solve: not worth a solver call.
bool undoes_last_step(const SearchNode& node, const Candidate& c) {
  return !c.add && node.step.action == "add" && node.step.changed && node.step.changed->same_surfaces(c.contact);
}

// Backtracking, last form (docs/METHOD.md section 3: further configurations for already-expanded
// pairs): once the open and retry queues are empty, the nodes expanded while an earlier milestone
// was the target are opened again, so that their case-1 candidates aim at the current one. E.g. a
// foot placed short at the start of a side-step: standing on the other foot already reaches the
// side-step's first milestone, the foot just placed cannot be stepped again from its own node
// (that would undo its step), but its parent, expanded again, places it towards the next one.
// Returns false when no node was expanded for an earlier milestone.
bool reopen_stale(std::vector<int>& expanded_for, int t, std::vector<int>& open) {
  bool any = false;
  for (int n = 0; n < int(expanded_for.size()); ++n)
    if (expanded_for[n] >= 0 && expanded_for[n] < t) {
      expanded_for[n] = -1;
      open.push_back(n);
      any = true;
    }
  return any;
}

}  // namespace

StanceSearch::StanceSearch(const Scenario& scenario, SearchOptions options)
    : scenario_(scenario), options_(options) {
  check_pinned_stances(scenario);  // before any search: an input error, not a failed search
}

bool StanceSearch::publish(SearchEvent event) {
  if (gate_ && !gate_->pass()) cancelled_ = true;
  if (stopped()) return false;
  event.number = next_event_++;
  if (observer_) observer_(event);
  return true;
}

SearchResult StanceSearch::run() {
  const auto start = Clock::now();
  const Scene& scene = scenario_.scene;
  const System& system = scene.system;
  SolverOptions solver_options = scenario_.solver;
  solver_options.cancel = &cancelled_;
  const PostureSolver solver(scene, solver_options);
  const Stance goal = scenario_.stance(scenario_.goal_stance);
  const GuidePath guide(system, scenario_.milestones, scenario_.milestone_masks);
  const int threads = options_.threads > 0 ? options_.threads : std::max(1u, std::thread::hardware_concurrency());
  // Candidate solves run in worker processes (Ipopt is not thread-safe): made before any solve.
  SolverPool pool(solver, threads);
  SearchResult result;
  std::vector<SearchNode>& tree = result.tree;
  auto elapsed = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  auto finish = [&](PlanStatus status, std::string message) -> SearchResult {
    result.status = status;
    result.message = std::move(message);
    result.wall_time_s = elapsed();
    result.plan.stats = {result.nodes_expanded, result.solver_calls, result.wall_time_s, threads};
    if (status != PlanStatus::Found) {
      SearchEvent failure;
      failure.kind = SearchEventKind::Failure;
      failure.message = std::string(to_string(status)) + ": " + result.message;
      failure.node = result.closest_node;
      failure.nodes = int(tree.size());
      if (result.closest_node >= 0) failure.stance = tree[result.closest_node].stance();
      if (observer_) {
        failure.number = next_event_++;
        observer_(failure);  // always delivered, even when cancelled
      }
    }
    return std::move(result);
  };

  // --- The root: sigma_init realised with every contact loaded.
  const PostureRequest root_request =
      scenario_.loaded_request(scenario_.initial_stance, scenario_.initial_configuration);
  const PostureResult root_result = solver.solve(root_request);
  ++result.solver_calls;
  result.solver_time_s += root_result.time_ms / 1000.0;
  if (root_result.status != PostureStatus::Solved)
    return finish(PlanStatus::InitialInfeasible, "the initial stance has no posture: " + root_result.message);
  auto make_node = [&](int parent, const PostureRequest& request, const PostureResult& solved, const Stance& stance,
                       const std::string& action, std::optional<Contact> changed) {
    SearchNode node;
    node.id = int(tree.size());
    node.parent = parent;
    node.depth = parent >= 0 ? tree[parent].depth + 1 : 0;
    for (const Contact& c : stance.contacts())
      for (size_t i = 0; i < request.contacts.size(); ++i)
        if (request.contacts[i].contact.same_surfaces(c)) node.placements.push_back(solved.placements[i]);
    node.step = make_plan_step(request, solved, stance, action, changed);
    return node;
  };
  tree.push_back(make_node(-1, root_request, root_result, scenario_.stance(scenario_.initial_stance), "initial", std::nullopt));

  int t = 0;  // the targeted milestone
  auto milestone_tolerance = [&](int m) {
    const auto& given = scenario_.milestone_tolerances;
    return m < int(given.size()) && given[m] > 0.0 ? given[m] : options_.milestone_tolerance;
  };
  // The guide path ranks the nodes; the stance term only counts once the last milestone is the
  // target (before that it would reward goal contacts made too early, e.g. hands on the desk while
  // still walking to it).
  auto cost = [&](const SearchNode& n) {
    const double d = guide.size() > 0 ? guide.distance_to(n.q(), t) : 0.0;
    const bool final_approach = t + 1 >= guide.size();
    return d + (final_approach ? options_.stance_weight * stance_difference(n.stance(), goal) : 0.0);
  };
  // A milestone may state which contacts are offered while it is the target (a phase of the task:
  // soles only while walking, thighs once sitting down).
  auto options_for_milestone = [&](int m) {
    SearchOptions o = options_;
    const auto& phases = scenario_.milestone_contact_pairs;
    if (m < int(phases.size()) && !phases[m].empty()) o.contact_pairs = phases[m];
    return o;
  };
  auto is_goal = [&](const SearchNode& n) {
    if (stance_difference(n.stance(), goal) != 0) return false;
    for (const StanceContact& g : scenario_.goal_stance) {
      if (!g.placement) continue;
      const int i = n.stance().find(g.contact);
      const Placement& p = n.placements[i];
      if (std::abs(p.x - g.placement->x) > options_.placement_tolerance ||
          std::abs(p.y - g.placement->y) > options_.placement_tolerance ||
          std::abs(std::remainder(p.theta - g.placement->theta, 2 * M_PI)) > options_.orientation_tolerance)
        return false;
    }
    return true;
  };
  auto already_in_tree = [&](const Stance& stance, const std::vector<Placement>& placements) {
    for (const SearchNode& n : tree) {
      if (!(n.stance() == stance)) continue;
      bool same = true;
      for (size_t i = 0; i < placements.size() && same; ++i)
        same = std::abs(n.placements[i].x - placements[i].x) <= options_.placement_tolerance &&
               std::abs(n.placements[i].y - placements[i].y) <= options_.placement_tolerance &&
               std::abs(std::remainder(n.placements[i].theta - placements[i].theta, 2 * M_PI)) <= options_.orientation_tolerance;
      if (same) return true;
    }
    return false;
  };
  auto closest = [&] {
    int best = 0;
    for (const SearchNode& n : tree) {
      const auto key = [&](const SearchNode& x) { return std::make_pair(stance_difference(x.stance(), goal), cost(x)); };
      if (key(n) < key(tree[best])) best = n.id;
    }
    return best;
  };
  // Every failure after the root: report the node closest to the goal (computed once, here).
  auto give_up = [&](PlanStatus status, std::string message) {
    result.closest_node = closest();
    result.milestone = t;
    return finish(status, std::move(message));
  };
  // Advances t past every milestone the tree already reaches; publishes each.
  auto advance_milestones = [&] {
    bool advanced = true;
    while (advanced && t + 1 < guide.size()) {
      advanced = false;
      for (const SearchNode& n : tree)
        if (guide.distance_to(n.q(), t) <= milestone_tolerance(t)) {
          ++t;
          advanced = true;
          SearchEvent e;
          e.kind = SearchEventKind::Milestone;
          e.node = n.id;
          e.stance = n.stance();
          e.q = n.q();
          e.milestone = t;
          e.nodes = int(tree.size());
          if (!publish(e)) return;
          break;
        }
    }
  };
  auto found = [&](int goal_node) {
    result.plan.steps = plan_to_node(tree, goal_node).steps;
    result.closest_node = goal_node;
    result.milestone = t;
    SearchEvent e;
    e.kind = SearchEventKind::PlanFound;
    e.node = goal_node;
    e.stance = tree[goal_node].stance();
    e.q = tree[goal_node].q();
    e.milestone = t;
    e.nodes = int(tree.size());
    publish(e);
    return finish(PlanStatus::Found, "plan of " + std::to_string(result.plan.steps.size()) + " steps");
  };

  {
    SearchEvent e;
    e.kind = SearchEventKind::Candidate;
    e.node = 0;
    e.stance = tree[0].stance();
    e.accepted = true;
    e.q = tree[0].q();
    e.contacts = tree[0].step.contacts;
    e.forces = tree[0].step.forces;
    e.time_ms = root_result.time_ms;
    e.iterations = root_result.iterations;
    e.torques = root_result.torques;
    e.residuals = root_result.residuals;
    e.nodes = 1;
    if (!publish(e)) return give_up(PlanStatus::Cancelled, "cancelled");
  }
  advance_milestones();
  if (is_goal(tree[0])) return found(0);

  std::vector<int> open = {0};
  // Backtracking queues: failed candidates that would add a goal contact are retried at once from
  // other initial guesses; the others when the open queue is empty.
  std::deque<Attempt> urgent, retries;
  // The milestone each node was last expanded for (-1: not yet), for the last form of backtracking.
  std::vector<int> expanded_for;
  while (true) {
    if (stopped()) return give_up(PlanStatus::Cancelled, "cancelled");
    if (elapsed() > options_.time_limit_s)
      return give_up(PlanStatus::TimeBudget, "no plan within " + std::to_string(options_.time_limit_s) + " s");
    if (result.nodes_expanded >= options_.max_nodes)
      return give_up(PlanStatus::NodeBudget, "no plan within " + std::to_string(options_.max_nodes) + " expanded nodes");
    std::vector<Attempt> batch;
    if (!urgent.empty()) {
      batch.assign(urgent.begin(), urgent.end());
      urgent.clear();
    } else if (!open.empty()) {
      // Pop the best open node (ties: the older node, for determinism).
      auto best = std::min_element(open.begin(), open.end(), [&](int a, int b) {
        const double ca = cost(tree[a]), cb = cost(tree[b]);
        return ca < cb || (ca == cb && a < b);
      });
      const int n = *best;
      open.erase(best);
      ++result.nodes_expanded;
      expanded_for.resize(tree.size(), -1);
      expanded_for[n] = t;
      SearchEvent e;
      e.kind = SearchEventKind::Expansion;
      e.node = n;
      e.stance = tree[n].stance();
      e.q = tree[n].q();
      e.contacts = tree[n].step.contacts;
      e.forces = tree[n].step.forces;
      e.iterations = tree[n].step.iterations;
      e.torques = tree[n].step.torques;
      e.milestone = t;
      e.nodes = int(tree.size());
      if (!publish(e)) return give_up(PlanStatus::Cancelled, "cancelled");
      const auto data = system_kinematics(system, tree[n].q());
      for (const Candidate& c : enumerate_candidates(scene, data, tree[n].stance(), goal, options_for_milestone(t)))
        if (!undoes_last_step(tree[n], c)) batch.push_back({n, c, 0});
    } else if (!retries.empty()) {
      // Backtracking (docs/METHOD.md section 3): the queue is empty, so retry earlier failures from
      // other initial guesses.
      batch.assign(retries.begin(), retries.end());
      retries.clear();
    } else if (reopen_stale(expanded_for, t, open)) {
      continue;
    } else {
      return give_up(PlanStatus::Exhausted, "every reachable stance was tried");
    }

    // Solve the batch, in parallel; results are used in batch order (deterministic).
    std::vector<PostureRequest> requests(batch.size());
    std::vector<PostureResult> results(batch.size());
    for (size_t i = 0; i < batch.size(); ++i) {
      const Attempt& a = batch[i];
      const SearchNode& node = tree[a.node];
      PostureRequest& r = requests[i];
      for (size_t k = 0; k < node.stance().contacts().size(); ++k)
        r.contacts.push_back({node.stance().contacts()[k], true, node.placements[k], std::nullopt, {}});
      const Eigen::VectorXd& q_ref = guide.size() > 0 ? guide.milestone(t) : node.q();
      if (a.candidate.add) {
        ContactTask added{a.candidate.contact, false, std::nullopt, std::nullopt, {}};
        // obj4 pulls the new contact towards its placement in the targeted milestone; a retry
        // aims at a point nearer the current one (a shorter step); never across another contact.
        const Placement now = measure_placement(scene, a.candidate.contact, node.q());
        const Placement aim = measure_placement(scene, a.candidate.contact, q_ref);
        const double share = std::pow(0.5, a.attempt);
        added.placement_target =
            step_target(scene, node.stance(), node.placements, a.candidate.contact, now, aim, share);
        // Heading for the goal (the last milestone), a goal contact with a stated placement is
        // first tried exactly there; a retry lets the solver choose.
        for (const StanceContact& g : scenario_.goal_stance)
          if (g.placement && g.contact.same_surfaces(a.candidate.contact) && a.attempt == 0 && t + 1 >= guide.size())
            added.placement = g.placement;
        r.contacts.push_back(added);
      } else {
        for (ContactTask& task : r.contacts)
          if (task.contact.same_surfaces(a.candidate.contact)) task.loaded = false;
      }
      // Initial guesses: the node's configuration; on the first retry the targeted milestone (often
      // in a better basin, e.g. sitting down); then perturbations of the node's configuration.
      r.q_init = a.attempt == 0 ? node.q() : a.attempt == 1 ? q_ref : perturbed(system, node.q(), a.node, a.attempt, i);
      r.q_ref = q_ref;
    }
    results = pool.solve_all(requests, &cancelled_);
    for (size_t i = 0; i < batch.size(); ++i) {
      if (stopped()) return give_up(PlanStatus::Cancelled, "cancelled");
      const Attempt& a = batch[i];
      const PostureResult& r = results[i];
      ++result.solver_calls;
      result.solver_time_s += r.time_ms / 1000.0;
      const SearchNode& parent = tree[a.node];
      const Stance next = a.candidate.add ? parent.stance().with(a.candidate.contact)
                                          : parent.stance().without(parent.stance().find(a.candidate.contact));
      SearchEvent e;
      e.kind = SearchEventKind::Candidate;
      e.parent = a.node;
      e.stance = next;
      e.candidate_case = a.candidate.add ? CandidateCase::Add : CandidateCase::Remove;
      e.changed = a.candidate.contact;
      e.status = r.status;
      e.message = r.message;
      e.q = r.q;
      for (const ContactTask& task : requests[i].contacts) e.contacts.push_back({task.contact, task.loaded});
      e.forces = r.forces;
      e.time_ms = r.time_ms;
      e.iterations = r.iterations;
      e.torques = r.torques;
      e.residuals = r.residuals;
      if (r.status == PostureStatus::Solved) {
        SearchNode child = make_node(a.node, requests[i], r, next, a.candidate.add ? "add" : "remove",
                                     a.candidate.contact);
        child.milestone = t;
        if (already_in_tree(child.stance(), child.placements)) {
          e.message = "already in the tree";
        } else {
          e.accepted = true;
          e.node = child.id;
          tree.push_back(std::move(child));
          open.push_back(e.node);
        }
      } else if (a.attempt < options_.max_retries) {
        const bool towards_goal = a.candidate.add && goal.find(a.candidate.contact) >= 0;
        (towards_goal ? urgent : retries).push_back({a.node, a.candidate, a.attempt + 1});
      }
      e.milestone = t;
      e.nodes = int(tree.size());
      if (!publish(e)) return give_up(PlanStatus::Cancelled, "cancelled");
      if (e.accepted) {
        if (is_goal(tree[e.node])) return found(e.node);
        advance_milestones();
      }
    }
  }
}

}  // namespace stanceplan
