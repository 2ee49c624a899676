#include "planner/plan/plan_timeline.h"

#include <algorithm>
#include <cmath>

namespace stanceplan {

bool has_motion(const Plan& plan) {
  return std::any_of(plan.steps.begin(), plan.steps.end(),
                     [](const PlanStep& s) { return s.motion && !s.motion->samples.empty(); });
}

TimelinePoint timeline_point(const Plan& plan, double position) {
  const int last = static_cast<int>(plan.steps.size()) - 1;
  if (last <= 0 || !(position > 0.0)) return {0, -1};  // NaN lands on step 0 too
  if (position >= static_cast<double>(last)) return {last, -1};
  const int i = static_cast<int>(std::floor(position));
  const double fraction = position - static_cast<double>(i);
  const std::optional<StepMotion>& motion = plan.steps[static_cast<size_t>(i + 1)].motion;
  const int n = motion ? static_cast<int>(motion->samples.size()) : 0;
  if (n == 0) return {i, -1};
  const int at = static_cast<int>(std::lround(fraction * static_cast<double>(n + 1)));
  if (at <= 0) return {i, -1};
  if (at > n) return {i + 1, -1};
  return {i + 1, at - 1};
}

}  // namespace stanceplan
