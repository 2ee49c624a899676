#pragma once
// A check of one transition of a plan (step `from` -> the next step `to`) that the search runs on
// the plan it found before it returns it: the motion between the two steps (planner/motion/,
// motion_transition_check.h). Declared here, below both the search and the motion planner, so that
// neither includes the other (docs/ARCHITECTURE.md).
#include <functional>

#include "planner/plan/plan.h"

namespace stanceplan {

// The motion from `from` to `to` (to.motion is not read): MotionStatus::Solved accepts the
// transition; any other status rejects it, its message saying why.
using TransitionCheck = std::function<StepMotion(const PlanStep& from, const PlanStep& to)>;

}  // namespace stanceplan
