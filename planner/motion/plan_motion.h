#pragma once
// The motion of a whole plan: for every step i > 0, the quasi-static path from step i-1 to step i
// (step_motion.h), stored in the step (PlanStep::motion). One planner, one solver, reused across
// steps.
#include <string>
#include <vector>

#include "planner/motion/step_motion.h"

namespace stanceplan {

struct PlanMotionSummary {
  std::vector<StepMotionResult> steps;  // index i-1: the motion into step i (samples moved out)
  int failed_steps = 0;
  std::string first_failure;  // "step 3: travel at s = 0.5: no posture (...)" ("" when none)
  bool solved() const { return failed_steps == 0; }
};

// Fills every step's motion (replacing any it had) and reports per step. A failed step keeps its
// samples up to the failure, with its status.
PlanMotionSummary add_motion(const Scene& scene, const SolverOptions& solver,
                             const MotionOptions& options, Plan& plan);

}  // namespace stanceplan
