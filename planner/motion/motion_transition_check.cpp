#include "planner/motion/motion_transition_check.h"

#include <utility>

namespace stanceplan {

MotionTransitionCheck::MotionTransitionCheck(const Scene& scene, const SolverOptions& solver,
                                             MotionOptions options)
    : planner_(scene, solver, std::move(options)) {}

StepMotion MotionTransitionCheck::check(const PlanStep& from, const PlanStep& to) {
  StepMotionResult result = planner_.plan(from, to);
  StepMotion motion = std::move(result.motion);
  result.motion.samples.clear();
  result.motion.status = motion.status;
  result.motion.message = motion.message;
  checked_.push_back(std::move(result));
  return motion;
}

TransitionCheck MotionTransitionCheck::as_check() {
  return [this](const PlanStep& from, const PlanStep& to) { return check(from, to); };
}

}  // namespace stanceplan
