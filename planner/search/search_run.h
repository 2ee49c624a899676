#pragma once
// One run of StanceSearch (Algorithm 1, docs/METHOD.md section 3), in named parts. Internal to
// planner/search/:
//   search_run.cpp       the main loop: budgets, which batch comes next, solving a batch in the
//                        solver pool and taking its results in batch order;
//   search_frontier.cpp  the tree and its frontier: node costs (distance to the targeted
//                        milestone), the goal test, loop avoidance, the closest node, milestones;
//   search_requests.cpp  candidate generation at an expansion and the solver request of each
//                        attempt (case 1 / case 2, step targets, initial guesses for retries);
//   search_event_builders.h  the events it publishes.
#include <chrono>
#include <deque>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "planner/search/candidates.h"
#include "planner/search/failure_memo.h"
#include "planner/search/guide_path.h"
#include "planner/search/stance_search.h"
#include "planner/solver/posture_solver.h"
#include "planner/solver/solver_pool.h"

namespace stanceplan {

// One candidate solve: a (node, candidate) pair and which attempt it is (0, then backtracking).
struct StanceSearch::Attempt {
  int node = -1;
  Candidate candidate;
  int attempt = 0;
  // support_share_score (m) of an addition when candidates are ordered (support_share.h), else 0.
  double share = 0.0;
};

class StanceSearch::Run {
 public:
  explicit Run(StanceSearch& search);
  SearchResult run();

 private:
  using Clock = std::chrono::steady_clock;

  // --- the main loop (search_run.cpp)
  std::optional<SearchResult> realise_root();
  std::optional<SearchResult> over_budget();
  // The next batch of attempts, or the search's end when nothing is left to try.
  std::optional<SearchResult> next_batch(std::vector<Attempt>& batch);
  void take_retries(std::vector<Attempt>& batch);
  // Takes solved batch results in batch order: new nodes, retries, events; the search's end when
  // the goal is reached or the search is cancelled.
  std::optional<SearchResult> take_results(const std::vector<Attempt>& batch,
                                           const std::vector<PostureRequest>& requests,
                                           const std::vector<PostureResult>& results);
  void remember_failure(const Attempt& attempt);
  void defer_other_facets(const Attempt& failed);
  // The goal reached at `goal`: the plan, once every transition on its path has passed the
  // transition check (lazy validation, stance_search.h); nullopt when one failed (its node was
  // dropped) and the search goes on.
  std::optional<SearchResult> reach_goal(int goal);
  // Drops node n and its subtree (its transition has no motion: `why`) from the frontier, the
  // pending candidates and the retries; publishes MotionFailed. False when cancelled at the event.
  bool drop(int n, const std::string& why);
  void retry_dropped(int n);
  SearchResult finish(PlanStatus status, std::string message);
  SearchResult give_up(PlanStatus status, std::string message);
  SearchResult found(int goal_node);
  double elapsed() const;       // wall time since the run started
  double held_time() const;     // of it, held by the step gate
  double running_time() const;  // less the transition checks': what the time budget counts
  std::string held_note() const;

  // --- the tree and its frontier (search_frontier.cpp)
  SearchNode make_node(int parent, const PostureRequest& request, const PostureResult& solved,
                       const Stance& stance, const std::string& action,
                       std::optional<Contact> changed) const;
  double milestone_tolerance(int m) const;
  bool reaches_milestone(const SearchNode& n, int t) const;
  double cost(const SearchNode& node) const;
  bool is_goal(const SearchNode& node) const;
  bool in_tree(const Stance& stance, const std::vector<Placement>& placements, int parent) const;
  bool already_in_tree(const SearchNode& node) const;
  bool removal_reaches_a_node(const SearchNode& node, const Candidate& c) const;
  bool addition_aims_at_a_node(const SearchNode& node, const Candidate& c) const;
  std::vector<Placement> child_placements(const SearchNode& node, const Stance& next,
                                          const Placement& added) const;
  int closest() const;
  void advance_milestones();
  bool skip_milestone();
  bool same_facets(const Attempt& a, const Attempt& b) const;
  // A node's rank in the open list: its cost, plus, once it is expanded for the targeted
  // milestone, the support share of its next pending candidate (both in metres).
  double priority(int n) const;
  int pop_best_open();

  // --- candidates and requests (search_requests.cpp)
  SearchOptions options_for_milestone(int m) const;
  // Publishes the expansion of node n and returns its first candidates as first attempts (the
  // rest wait in pending_, lazy expansion); nullopt when the search was cancelled at the event.
  std::optional<std::vector<Attempt>> expand(int n);
  // The next options_.expansion_batch pending attempts of node n (all with 0); n goes back to the
  // open list while some are left. One alone when solves_alone (SearchOptions::batch_margin).
  std::vector<Attempt> take_pending(int n);
  bool solves_alone(const std::deque<Attempt>& pending) const;
  // Where attempt `attempt` of adding `added` from `node` aims s1: obj4's step target, and the
  // goal's stated placement when that attempt is made exactly there; `now` is s1's placement at
  // the node, where the step starts.
  struct AdditionAim {
    Placement now;
    Placement target;
    std::optional<Placement> placement;
  };
  AdditionAim addition_aim(const SearchNode& node, const Contact& added, int attempt) const;
  PostureRequest request_for(const Attempt& attempt, size_t index) const;
  bool worth_retrying(const Attempt& a, const PostureResult& r) const;
  bool urgent(const Attempt& a) const;

  StanceSearch& search_;
  const Problem& problem_;
  const SearchOptions& options_;
  const Clock::time_point start_;
  const PostureSolver solver_;
  const Stance goal_;
  const GuidePath guide_;
  const int threads_;
  // Worker processes (Ipopt is not thread-safe): the caller's (StanceSearch::set_solver_pool),
  // else the run's own, made before any solve.
  std::unique_ptr<SolverPool> own_pool_;
  SolverPool& pool_;
  SearchResult result_;
  std::vector<SearchNode>& tree_;
  int t_ = 0;              // the targeted milestone
  std::vector<int> open_;  // nodes not yet expanded
  // Backtracking queues: failed candidates that would add a goal contact the guide's posture
  // realises are retried at once from other initial guesses (urgent()); the others when the open
  // queue is empty.
  std::deque<Attempt> urgent_, retries_;
  FailureMemo failures_;  // candidates that failed every attempt (defer_repeated_failures)
  NormalAngleTable angles_{problem_.scene};  // the normal-angle rule's bounds (candidates.h)
  ReachTable reach_{problem_.scene};         // the reach rule's bounds (candidates.h)
  // The milestone each node was last expanded for (-1: not yet), for the last form of
  // backtracking.
  std::vector<int> expanded_for_;
  // Lazy expansion: per node, the first attempts of its last expansion not yet solved, in order.
  std::vector<std::deque<Attempt>> pending_;
};

}  // namespace stanceplan
