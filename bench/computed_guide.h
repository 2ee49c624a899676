#pragma once
// A scenario given the guide `stanceplan plan` gives it (planner/io/scenario_guide.h): computed
// when it has none, its written guide completed where partial, the goal contacts that only steady
// the body offered last unless the file states some.
#include <optional>

#include "planner/io/scenario_guide.h"

namespace stanceplan::bench {

// False when a guide was needed and failed.
inline bool guide_as_plan_gives(Scenario& s) {
  const std::optional<ComputedGuide> guide = complete_scenario_guide(s);
  return !guide || guide->status == GuideStatus::Computed;
}

}  // namespace stanceplan::bench
