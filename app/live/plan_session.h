#pragma once
// One stance search on a worker thread (docs/ARCHITECTURE.md, Threads). Every SearchEvent is stored
// in order in the session; consumers (the snapshot writer, the panel, the progress line) read them
// with their own cursor and never block the search: the search only takes the session's mutex
// long enough to append an event. The step gate is the one way to hold the search (pause / step).
#include <chrono>
#include <condition_variable>
#include <exception>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "planner/io/scenario.h"
#include "planner/motion/motion_transition_check.h"
#include "planner/search/search_events.h"
#include "planner/search/stance_search.h"
#include "planner/solver/posture_solver.h"
#include "planner/solver/solver_pool.h"

namespace stanceplan::app {

class PlanSession {
 public:
  // Makes the solver worker processes at once, on the calling thread (before the caller starts
  // other threads: solver_pool.h); the scenario outlives the session. With `motion`, the search
  // checks the motion of each transition of a plan it finds (lazy validation, stance_search.h):
  // a plan found carries its motion, and a transition without one is dropped.
  PlanSession(const Scenario& scenario, SearchOptions options,
              std::optional<MotionOptions> motion = std::nullopt);
  ~PlanSession();  // cancels and joins
  PlanSession(const PlanSession&) = delete;
  PlanSession& operator=(const PlanSession&) = delete;

  void start();  // launches the worker thread (once per run)
  // A new search from the start with the same options, solver processes and gate (the panel's
  // Run again after a failure or a cancel): cancels and joins the current one, forgets its events
  // and result, and starts. The gate keeps its pause state; its cancellation is lifted.
  void restart();
  StepGate& gate();  // pause / step / resume, used by the panel
  void cancel();     // cancels search and gate; returns at once
  // Async-signal-safe part of cancel(), for SIGINT handlers: one atomic store. A search held by a
  // paused gate stays held; the command line never pauses it.
  void cancel_search() { search_->cancel(); }
  bool finished() const;
  size_t event_count() const;
  SearchEvent event(size_t index) const;  // copy, thread-safe
  // Seconds from start() to the moment the event was published.
  double event_time_s(size_t index) const;
  // Blocks until event_count() > index or the session finished or timeout; true if available.
  bool wait_for_event(size_t index, std::chrono::milliseconds timeout) const;
  // Blocks until the session finished or timeout; true when finished.
  bool wait_until_finished(std::chrono::milliseconds timeout) const;
  std::optional<SearchResult> result() const;  // set once finished
  // What ended the search thread when it threw (bad input met during the search): result() then
  // stays empty. Null otherwise.
  std::exception_ptr error() const;
  const Scenario& scenario() const { return scenario_; }
  // The transitions the current run checked (their figures; empty without `motion`). Read once
  // finished() only: the search thread appends to it.
  std::vector<StepMotionResult> motion_checks() const;

 private:
  void record(const SearchEvent& event);
  void run();
  std::unique_ptr<StanceSearch> make_search();

  const Scenario& scenario_;
  const SearchOptions options_;
  const std::optional<MotionOptions> motion_;
  std::unique_ptr<MotionTransitionCheck> motion_check_;  // made with each search
  PostureSolver pool_solver_;                            // the solver the worker processes copy
  SolverPool pool_;
  std::unique_ptr<StanceSearch> search_;
  StepGate gate_;
  std::thread worker_;
  std::chrono::steady_clock::time_point start_time_;

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  std::vector<SearchEvent> events_;
  std::vector<double> times_s_;
  std::optional<SearchResult> result_;
  std::exception_ptr error_;
  bool finished_ = false;
};

}  // namespace stanceplan::app
