#include "planner/motion/plan_motion.h"

namespace stanceplan {

PlanMotionSummary add_motion(const Scene& scene, const SolverOptions& solver,
                             const MotionOptions& options, Plan& plan) {
  PlanMotionSummary summary;
  StepMotionPlanner planner(scene, solver, options);
  for (size_t i = 1; i < plan.steps.size(); ++i) {
    StepMotionResult result = planner.plan(plan.steps[i - 1], plan.steps[i]);
    if (result.motion.status != MotionStatus::Solved && summary.failed_steps++ == 0)
      summary.first_failure = "step " + std::to_string(i) + ": " + result.motion.message;
    plan.steps[i].motion =
        StepMotion{result.motion.status, result.motion.message, std::move(result.motion.samples)};
    result.motion.samples.clear();
    summary.steps.push_back(std::move(result));
  }
  return summary;
}

}  // namespace stanceplan
