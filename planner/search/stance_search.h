#pragma once
// The multi-contact stance planner of Bouyarmane & Kheddar, "Humanoid Robot Locomotion and
// Manipulation Step Planning", Advanced Robotics 26(10), 2012 (docs/METHOD.md section 3,
// Algorithm 1): a greedy best-first search over stances. Each candidate (add a contact: case 1;
// remove one: case 2) is checked by the IK-statics solver; the cost is the distance to the targeted
// milestone of the guide path. Adds loop avoidance, backtracking, budgets, cancellation, events and
// a step gate. Deterministic: the plan does not depend on the thread count.
//
// With a transition check (set_transition_check: the motion between two steps, planner/motion/),
// a plan is validated lazily before it is returned, as Lazy PRM validates a path's edges (Bohlin &
// Kavraki, "Path Planning Using Lazy PRM", ICRA 2000): the transitions from the root to the goal
// are checked in order, each once (a node keeps its motion); the first without a motion drops its
// node and the node's subtree (SearchNode::dropped, a MotionFailed event), and the search goes on
// from its frontier, first with the dropped node's candidate from its parent's next initial guess.
// A dropped node still counts for loop avoidance from its parent, so the same transition is not
// made again; reached from another node, its stance is a new transition.
#include <atomic>
#include <chrono>
#include <string>
#include <vector>

#include "planner/plan/plan.h"
#include "planner/plan/problem.h"
#include "planner/plan/transition_check.h"
#include "planner/search/guide_path.h"
#include "planner/search/search_events.h"
#include "planner/search/search_options.h"

namespace stanceplan {

enum class PlanStatus { Found, Exhausted, NodeBudget, TimeBudget, Cancelled, InitialInfeasible };
const char* to_string(PlanStatus status);

struct SearchNode {
  int id = 0;
  int parent = -1;
  int depth = 0;
  int milestone = 0;                  // the milestone targeted when the node was made
  std::vector<Placement> placements;  // per stance contact, realised at step.q
  PlanStep step;                      // the transition that made it (its stance, q, forces, ...)
  int attempt = 0;  // which attempt of its candidate made it (0: from the parent's configuration)
  // Its transition from the parent (or an ancestor's) has no motion: never part of a plan.
  bool dropped = false;
  const Stance& stance() const { return step.stance; }
  const Eigen::VectorXd& q() const { return step.q; }
};

struct SearchResult {
  PlanStatus status = PlanStatus::Exhausted;
  std::string message;
  Plan plan;  // the sequence, when found
  std::vector<SearchNode> tree;
  int closest_node = -1;       // the node whose stance is closest to the goal's
  int milestone = 0;           // the milestone targeted at the end: those reached or skipped
  int milestones_skipped = 0;  // of those, skipped (SearchOptions::skip_unreached_milestones)
  int nodes_expanded = 0;
  int solver_calls = 0;
  double wall_time_s = 0.0;
  // Of wall_time_s, the time the step gate held the search (paused, stepped, throttled by an
  // observer): it does not count against SearchOptions::time_limit_s.
  double held_time_s = 0.0;
  double solver_time_s = 0.0;  // summed over solves
  // The transition check (lazy validation): transitions checked, those without a motion, and the
  // wall time the checks took (part of wall_time_s, not counted by SearchOptions::time_limit_s).
  int transitions_checked = 0;
  int transitions_dropped = 0;
  double check_time_s = 0.0;
};

class SolverPool;

// How many solver processes a search with these options uses (SearchOptions::threads, or one per
// core when 0).
int solver_processes(const SearchOptions& options);

class StanceSearch {
 public:
  StanceSearch(const Problem& problem, SearchOptions options);

  void set_observer(SearchObserver observer) { observer_ = std::move(observer); }
  // The worker processes for candidate solves, made by the caller before its other threads start
  // (solver_pool.h; solver_processes(options) of them, for the plan's stats to be true) and kept
  // alive for the run. None: the run makes its own when it starts.
  void set_solver_pool(SolverPool* pool) { pool_ = pool; }
  void set_gate(StepGate* gate) { gate_ = gate; }
  // Lazy validation of the plan found (above); none: the plan's transitions are not checked.
  void set_transition_check(TransitionCheck check) { check_ = std::move(check); }
  // Thread-safe: the search stops before its next solver call.
  void cancel() { cancelled_ = true; }
  // The flag cancel() sets, for the solver of a transition check (SolverOptions::cancel): a check
  // then ends within a solver iteration and the search reports the cancel.
  const std::atomic<bool>* cancel_flag() const { return &cancelled_; }

  SearchResult run();

 private:
  struct Attempt;
  class Run;  // one run, in named parts (search_run.h)
  bool publish(SearchEvent event);
  bool stopped() const { return cancelled_.load(); }

  const Problem& problem_;
  SearchOptions options_;
  SearchObserver observer_;
  StepGate* gate_ = nullptr;
  SolverPool* pool_ = nullptr;
  TransitionCheck check_;
  std::chrono::steady_clock::duration held_{};  // in the gate; written by the search thread only
  std::atomic<bool> cancelled_{false};
  int next_event_ = 0;
};

}  // namespace stanceplan
