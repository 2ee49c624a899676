// The main loop of a search run (search_run.h): Algorithm 1 of docs/METHOD.md section 3 with
// budgets, backtracking and events.
#include "planner/search/search_run.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iterator>
#include <sstream>
#include <utility>

#include "planner/model/kinematics.h"
#include "planner/search/plan_path.h"
#include "planner/search/search_event_builders.h"

namespace stanceplan {
namespace {

// "120 s", "0.25 s", "42.5 s": seconds for people (3 significant digits below 100 s).
std::string seconds(double s) {
  std::ostringstream out;
  out << std::setprecision(s >= 100 ? 6 : 3) << s << " s";
  return out.str();
}

SolverOptions cancellable(SolverOptions options, const std::atomic<bool>* cancel) {
  options.cancel = cancel;
  return options;
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
    if (expanded_for[size_t(n)] >= 0 && expanded_for[size_t(n)] < t) {
      expanded_for[size_t(n)] = -1;
      open.push_back(n);
      any = true;
    }
  return any;
}

}  // namespace

StanceSearch::Run::Run(StanceSearch& search)
    : search_(search),
      problem_(search.problem_),
      options_(search.options_),
      start_(Clock::now()),
      solver_(problem_.scene, cancellable(problem_.solver, &search.cancelled_)),
      goal_(problem_.stance(problem_.goal_stance)),
      guide_(problem_.scene.system, problem_.milestones, problem_.milestone_masks),
      threads_(solver_processes(options_)),
      own_pool_(search.pool_ ? nullptr : std::make_unique<SolverPool>(solver_, threads_)),
      pool_(search.pool_ ? *search.pool_ : *own_pool_),
      tree_(result_.tree) {}

SearchResult StanceSearch::Run::run() {
  if (auto end = realise_root()) return std::move(*end);
  while (true) {
    if (auto end = over_budget()) return std::move(*end);
    std::vector<Attempt> batch;
    if (auto end = next_batch(batch)) return std::move(*end);
    if (batch.empty()) continue;  // nodes were reopened: choose again
    // Solve the batch, in parallel; results are used in batch order (deterministic).
    std::vector<PostureRequest> requests(batch.size());
    for (size_t i = 0; i < batch.size(); ++i) requests[i] = request_for(batch[i], i);
    const std::vector<PostureResult> results = pool_.solve_all(requests, &search_.cancelled_);
    if (auto end = take_results(batch, requests, results)) return std::move(*end);
  }
}

// The root: sigma_init realised with every contact loaded.
std::optional<SearchResult> StanceSearch::Run::realise_root() {
  const PostureRequest request =
      problem_.loaded_request(problem_.initial_stance, problem_.initial_configuration);
  const PostureResult solved = solver_.solve(request);
  ++result_.solver_calls;
  result_.solver_time_s += solved.time_ms / 1000.0;
  // A cancel during the root's solve stops it: that says nothing of the initial stance.
  if (search_.stopped()) return give_up(PlanStatus::Cancelled, "cancelled");
  if (solved.status != PostureStatus::Solved)
    return finish(PlanStatus::InitialInfeasible,
                  "the initial stance has no posture: " + solved.message);
  tree_.push_back(make_node(-1, request, solved, problem_.stance(problem_.initial_stance),
                            "initial", std::nullopt));
  if (!search_.publish(root_event(tree_[0], solved)))
    return give_up(PlanStatus::Cancelled, "cancelled");
  advance_milestones();
  if (is_goal(tree_[0])) return found(0);
  open_ = {0};
  return std::nullopt;
}

std::optional<SearchResult> StanceSearch::Run::over_budget() {
  if (search_.stopped()) return give_up(PlanStatus::Cancelled, "cancelled");
  if (running_time() > options_.time_limit_s)
    return give_up(PlanStatus::TimeBudget,
                   "no plan within " + seconds(options_.time_limit_s) + " of search" + held_note());
  if (result_.nodes_expanded >= options_.max_nodes)
    return give_up(PlanStatus::NodeBudget,
                   "no plan within " + std::to_string(options_.max_nodes) + " expanded nodes");
  return std::nullopt;
}

// Urgent retries first, then the best open node, then (backtracking, docs/METHOD.md section 3)
// the other retries from other initial guesses, then nodes expanded for an earlier milestone.
std::optional<SearchResult> StanceSearch::Run::next_batch(std::vector<Attempt>& batch) {
  if (!urgent_.empty()) {
    batch.assign(urgent_.begin(), urgent_.end());
    urgent_.clear();
  } else if (!open_.empty()) {
    const int n = pop_best_open();
    // Lazy expansion: a node expanded for the targeted milestone goes on with its candidates;
    // for an earlier one (or never), it is expanded (again: its case-1 candidates aim anew).
    if (n < int(pending_.size()) && !pending_[size_t(n)].empty() &&
        expanded_for_[size_t(n)] == t_) {
      batch = take_pending(n);
      return std::nullopt;
    }
    std::optional<std::vector<Attempt>> expanded = expand(n);
    if (!expanded) return give_up(PlanStatus::Cancelled, "cancelled");
    batch = std::move(*expanded);
  } else if (!retries_.empty()) {
    take_retries(batch);
  } else if (!reopen_stale(expanded_for_, t_, open_) && !skip_milestone()) {
    return give_up(PlanStatus::Exhausted, "every reachable stance was tried");
  }
  return std::nullopt;
}

// Every stance tried and the targeted milestone still out of reach: aim at the next one, every
// node open again (SearchOptions::skip_unreached_milestones). Published as a Milestone event at
// the node nearest to the skipped milestone, with a message.
bool StanceSearch::Run::skip_milestone() {
  if (!options_.skip_unreached_milestones || t_ + 1 >= guide_.size()) return false;
  int nearest = -1;
  double nearest_distance = INFINITY;
  for (const SearchNode& n : tree_) {
    const double d = n.dropped ? INFINITY : guide_.distance_to(n.q(), t_);
    if (d < nearest_distance) nearest_distance = d, nearest = n.id;
  }
  if (nearest < 0) return false;
  std::ostringstream why;
  why << "skipped milestone " << t_ + 1 << ": every stance was tried and the nearest node is "
      << std::fixed << std::setprecision(3) << nearest_distance << " from it (tolerance "
      << milestone_tolerance(t_) << ")";
  ++t_;
  ++result_.milestones_skipped;
  SearchEvent e =
      node_event(SearchEventKind::Milestone, tree_[size_t(nearest)], t_, int(tree_.size()));
  e.message = why.str();
  search_.publish(e);  // a cancel ends the run at the next budget check
  reopen_stale(expanded_for_, t_, open_);
  return true;
}

// Backtracking with lazy expansion: the retries most likely to carry their share first
// (support_share.h; ties in the order they failed), options_.expansion_batch at a time; every one
// at once when expansion_batch is 0.
void StanceSearch::Run::take_retries(std::vector<Attempt>& batch) {
  size_t count = retries_.size();
  if (options_.expansion_batch > 0) {
    std::stable_sort(retries_.begin(), retries_.end(),
                     [](const Attempt& a, const Attempt& b) { return a.share < b.share; });
    count = std::min(count, size_t(options_.expansion_batch));
  }
  batch.assign(retries_.begin(), retries_.begin() + long(count));
  retries_.erase(retries_.begin(), retries_.begin() + long(count));
}

// Another attempt from another initial guess, unless the budget of retries is spent or the
// first solve found the candidate infeasible (Ipopt's local infeasibility, a failed restoration,
// an active set that keeps growing: PostureStatus::Infeasible). A heuristic, measured on the 23
// untuned, paper and guide-free runs at 1e723bf (`plan --verbose`): no candidate retried after an
// infeasible attempt was ever solved (7 of 7 failed every retry; 3 of 47, one of them into a new
// node, in the untuned desk started 1 cm off, a run that found no plan), while half of those
// retried after an iteration limit were (17 of 34).
bool StanceSearch::Run::worth_retrying(const Attempt& a, const PostureResult& r) const {
  return a.attempt < options_.max_retries && r.status != PostureStatus::Infeasible;
}

// A failed goal contact is retried at once when the guide's posture realises it (its support
// share within placement_tolerance, support_share.h: a thigh over the seat at the sitting
// milestone); one the guide's posture is far from (a thigh 0.4 m above the seat while walking
// past the chair) waits for backtracking like any other failure. All at once (expansion_batch 0)
// or unordered, every share is 0: every goal contact is retried at once, as in Algorithm 1.
bool StanceSearch::Run::urgent(const Attempt& a) const {
  return a.candidate.add && goal_.find(a.candidate.contact) >= 0 &&
         a.share <= options_.placement_tolerance;
}

std::optional<SearchResult> StanceSearch::Run::take_results(
    const std::vector<Attempt>& batch, const std::vector<PostureRequest>& requests,
    const std::vector<PostureResult>& results) {
  for (size_t i = 0; i < batch.size(); ++i) {
    if (search_.stopped()) return give_up(PlanStatus::Cancelled, "cancelled");
    const Attempt& a = batch[i];
    const PostureResult& r = results[i];
    ++result_.solver_calls;
    result_.solver_time_s += r.time_ms / 1000.0;
    if (tree_[size_t(a.node)].dropped) continue;  // a plan through it was found and had no motion
    const Stance& from = tree_[size_t(a.node)].stance();
    const Stance next = a.candidate.add ? from.with(a.candidate.contact)
                                        : from.without(from.find(a.candidate.contact));
    SearchEvent e =
        candidate_event(a.node, next, a.candidate.add, a.candidate.contact, requests[i], r);
    if (r.status == PostureStatus::Solved) {
      SearchNode child = make_node(a.node, requests[i], r, next, a.candidate.add ? "add" : "remove",
                                   a.candidate.contact);
      child.milestone = t_;
      child.attempt = a.attempt;
      if (already_in_tree(child)) {
        e.message = "already in the tree";
      } else {
        e.accepted = true;
        e.node = child.id;
        tree_.push_back(std::move(child));
        open_.push_back(e.node);
      }
    } else {
      if (a.attempt == 0) remember_failure(a);
      if (a.attempt == 0 && options_.defer_repeated_failures && a.candidate.add)
        defer_other_facets(a);
      if (worth_retrying(a, r))
        (urgent(a) ? urgent_ : retries_).push_back({a.node, a.candidate, a.attempt + 1, a.share});
    }
    e.milestone = t_;
    e.nodes = int(tree_.size());
    if (!search_.publish(e)) return give_up(PlanStatus::Cancelled, "cancelled");
    if (e.accepted && is_goal(tree_[size_t(e.node)])) {
      if (auto end = reach_goal(e.node)) return end;
    } else if (e.accepted) {
      advance_milestones();
    }
  }
  return std::nullopt;
}

// An addition failed its first attempt: the node's other pending additions of a surface of the
// same link on the same partner surface (another facet of the cylinder on platform B while both
// arms hold it) wait for backtracking (SearchOptions::defer_repeated_failures); a node left with
// none leaves the open list, so that it is not expanded anew with them.
void StanceSearch::Run::defer_other_facets(const Attempt& failed) {
  if (size_t(failed.node) >= pending_.size()) return;
  std::deque<Attempt>& pending = pending_[size_t(failed.node)];
  const auto same = [&](const Attempt& a) { return same_facets(a, failed); };
  std::copy_if(pending.begin(), pending.end(), std::back_inserter(retries_), same);
  pending.erase(std::remove_if(pending.begin(), pending.end(), same), pending.end());
  if (pending.empty())
    open_.erase(std::remove(open_.begin(), open_.end(), failed.node), open_.end());
}

// A candidate failed its first attempt (from the node's own configuration): remembered with the
// situation it was tried from.
void StanceSearch::Run::remember_failure(const Attempt& a) {
  if (!options_.defer_repeated_failures) return;
  const SearchNode& node = tree_[size_t(a.node)];
  const auto data = system_kinematics(problem_.scene.system, node.q());
  failures_.record(problem_.scene, data, node.q(), node.stance(), a.candidate);
}

std::optional<SearchResult> StanceSearch::Run::reach_goal(int goal) {
  if (!search_.check_) return found(goal);
  std::vector<int> path;
  for (int n = goal; n > 0; n = tree_[size_t(n)].parent) path.push_back(n);
  for (auto n = path.rbegin(); n != path.rend(); ++n) {
    SearchNode& node = tree_[size_t(*n)];
    if (node.step.motion) continue;  // checked when an earlier plan went through it
    if (search_.stopped()) return give_up(PlanStatus::Cancelled, "cancelled");
    const auto started = Clock::now();
    StepMotion motion = search_.check_(tree_[size_t(node.parent)].step, node.step);
    result_.check_time_s += std::chrono::duration<double>(Clock::now() - started).count();
    if (search_.stopped()) return give_up(PlanStatus::Cancelled, "cancelled");  // not a failure
    ++result_.transitions_checked;
    if (motion.status != MotionStatus::Solved) {
      ++result_.transitions_dropped;
      if (!drop(*n, motion.message)) return give_up(PlanStatus::Cancelled, "cancelled");
      return std::nullopt;
    }
    node.step.motion = std::move(motion);
  }
  return found(goal);
}

bool StanceSearch::Run::drop(int n, const std::string& why) {
  tree_[size_t(n)].dropped = true;
  for (SearchNode& node : tree_)  // children come after their parent
    if (node.parent >= 0 && tree_[size_t(node.parent)].dropped) node.dropped = true;
  const auto dropped = [&](int k) { return tree_[size_t(k)].dropped; };
  open_.erase(std::remove_if(open_.begin(), open_.end(), dropped), open_.end());
  for (std::deque<Attempt>* queue : {&urgent_, &retries_})
    queue->erase(std::remove_if(queue->begin(), queue->end(),
                                [&](const Attempt& a) { return dropped(a.node); }),
                 queue->end());
  for (int k = 0; k < int(tree_.size()); ++k) {
    if (!dropped(k)) continue;
    if (k < int(pending_.size())) pending_[size_t(k)].clear();
    if (k < int(expanded_for_.size())) expanded_for_[size_t(k)] = -1;  // never reopened
  }
  retry_dropped(n);
  SearchEvent e =
      node_event(SearchEventKind::MotionFailed, tree_[size_t(n)], t_, int(tree_.size()));
  e.parent = tree_[size_t(n)].parent;
  e.message = "no motion from node " + std::to_string(e.parent) + ": " + why;
  return search_.publish(std::move(e));
}

// The candidate that made a dropped node, tried again at once from its parent from the next
// initial guess: an addition then aims at a shorter step (request_for), often one the moving link
// can reach (a foot set down nearer where it hangs).
void StanceSearch::Run::retry_dropped(int n) {
  const SearchNode& node = tree_[size_t(n)];
  if (node.attempt >= options_.max_retries || !node.step.changed) return;
  const Candidate candidate{node.step.action == "add", *node.step.changed};
  urgent_.push_front({node.parent, candidate, node.attempt + 1, 0.0});
}

SearchResult StanceSearch::Run::finish(PlanStatus status, std::string message) {
  result_.status = status;
  result_.message = std::move(message);
  result_.wall_time_s = elapsed();
  result_.held_time_s = held_time();
  result_.plan.stats = {result_.nodes_expanded, result_.solver_calls, result_.wall_time_s,
                        threads_};
  if (status != PlanStatus::Found && search_.observer_) {
    SearchEvent failure = failure_event(std::string(to_string(status)) + ": " + result_.message,
                                        tree_, result_.closest_node);
    failure.number = search_.next_event_++;
    search_.observer_(failure);  // always delivered, even when cancelled
  }
  return std::move(result_);
}

// Every failure after the root: report the node closest to the goal (computed once, here).
SearchResult StanceSearch::Run::give_up(PlanStatus status, std::string message) {
  result_.closest_node = closest();
  result_.milestone = t_;
  return finish(status, std::move(message));
}

SearchResult StanceSearch::Run::found(int goal_node) {
  result_.plan.steps = plan_to_node(tree_, goal_node).steps;
  result_.closest_node = goal_node;
  result_.milestone = t_;
  search_.publish(
      node_event(SearchEventKind::PlanFound, tree_[size_t(goal_node)], t_, int(tree_.size())));
  return finish(PlanStatus::Found,
                "plan of " + std::to_string(result_.plan.steps.size()) + " steps");
}

double StanceSearch::Run::elapsed() const {
  return std::chrono::duration<double>(Clock::now() - start_).count();
}

double StanceSearch::Run::held_time() const {
  return std::chrono::duration<double>(search_.held_).count();
}

// The transition checks are the motion planner's time, bounded by its own budgets (MotionOptions).
double StanceSearch::Run::running_time() const {
  return elapsed() - held_time() - result_.check_time_s;
}

// " (and 42.5 s held by the step gate)", or "" when the gate never held the search.
std::string StanceSearch::Run::held_note() const {
  const double held = held_time();
  return held >= 0.05 ? " (and " + seconds(held) + " held by the step gate)" : "";
}

}  // namespace stanceplan
