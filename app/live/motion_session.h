#pragma once
// The motion between a found plan's steps (planner/motion/) computed on a worker thread, one step
// at a time, for a consumer that shows each step's motion as soon as it exists (the panel's
// timeline). Same threading rules as PlanSession: the consumer copies under the lock, the worker
// never waits on it. A step whose motion fails keeps none (its failure is recorded): the plan
// stays one `certify` accepts, and the timeline holds the step there as before. A step that
// already has a solved motion (the search checked it: PlanSession with motion) keeps it.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "planner/motion/motion_options.h"
#include "planner/plan/plan.h"
#include "planner/scene/scene.h"
#include "planner/solver/posture_request.h"

namespace stanceplan::app {

struct MotionProgress {
  int steps_done = 0;    // motions into steps 1..steps_done tried (the plan has steps - 1 motions)
  int steps_failed = 0;  // of those, the ones kept without motion
  std::string first_failure;  // "step 3: ..." ("" when none)
  bool finished = false;      // every step tried, or cancelled
  bool cancelled = false;
};

class MotionSession {
 public:
  // The scene outlives the session; the plan is copied.
  MotionSession(const Scene& scene, SolverOptions solver, MotionOptions options, Plan plan);
  ~MotionSession();  // cancels and joins (after the step being computed)
  MotionSession(const MotionSession&) = delete;
  MotionSession& operator=(const MotionSession&) = delete;

  void start();   // launches the worker thread (once)
  void cancel();  // the worker stops before its next step; returns at once

  MotionProgress progress() const;
  // The plan with the motions of the steps done so far (a copy).
  Plan plan() const;
  // Blocks until every step was tried (or cancelled) or timeout; true when finished.
  bool wait_until_finished(std::chrono::milliseconds timeout) const;

 private:
  void run();

  const Scene& scene_;
  const SolverOptions solver_;
  const MotionOptions options_;
  std::atomic<bool> cancelled_{false};
  std::thread worker_;

  mutable std::mutex mutex_;
  mutable std::condition_variable changed_;
  Plan plan_;
  MotionProgress progress_;
};

}  // namespace stanceplan::app
