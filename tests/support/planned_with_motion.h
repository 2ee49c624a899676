#pragma once
// A scenario planned as `plan --motion` plans it: one solver process, the search checking the
// motion of each transition of the plan it finds (MotionTransitionCheck) and dropping those
// without.
#include <vector>

#include "planner/io/scenario.h"
#include "planner/motion/motion_transition_check.h"
#include "planner/search/stance_search.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan::test {

struct PlannedWithMotion {
  SearchResult result;
  std::vector<StepMotionResult> checks;  // every transition checked, in order
};

inline PlannedWithMotion plan_with_motion(const Scenario& scenario) {
  MotionTransitionCheck check(scenario.scene, scenario.solver, MotionOptions{});
  StanceSearch search(scenario, one_process(scenario));
  search.set_transition_check(check.as_check());
  PlannedWithMotion planned{search.run(), {}};
  planned.checks = check.checked();
  return planned;
}

}  // namespace stanceplan::test
