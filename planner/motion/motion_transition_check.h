#pragma once
// The motion planner as the search's transition check (planner/plan/transition_check.h): the
// search asks it for the motion of each transition of a plan it found, and drops a transition
// that has none (lazy validation, planner/search/stance_search.h). It keeps one StepMotionPlanner
// (one solver, reused) and what each check cost, for the motion's timing line.
#include <vector>

#include "planner/motion/step_motion.h"
#include "planner/plan/transition_check.h"

namespace stanceplan {

class MotionTransitionCheck {
 public:
  MotionTransitionCheck(const Scene& scene, const SolverOptions& solver, MotionOptions options);

  StepMotion check(const PlanStep& from, const PlanStep& to);
  // A TransitionCheck calling check() on this object, which must outlive it.
  TransitionCheck as_check();

  // Every check so far, in order (their samples moved out: the search keeps them).
  const std::vector<StepMotionResult>& checked() const { return checked_; }
  void clear() { checked_.clear(); }

 private:
  StepMotionPlanner planner_;
  std::vector<StepMotionResult> checked_;
};

}  // namespace stanceplan
