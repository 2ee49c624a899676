#pragma once
// The guide a scenario is planned with, the same for `stanceplan plan`, `guide`, the panel, the
// main job, the benchmarks and the tests (docs/METHOD.md section 3, "The guide computed"):
//  - no `guide:` section: the guide computed for the whole problem (guide_planner.h), read into
//    the scenario exactly as its `guide:` section would be read (read_guide_section);
//  - a partial `guide:` section: completed where it leaves out a root that must move or the
//    posture change (partial_guide.h, complete_written_guide);
//  - either way, when the program computed a guide, the goal contacts that only steady the body
//    are offered last (ContactPhases::last, contact_phases.h) unless the file states its own
//    search.last_contacts: a forearm put down on the desk before the thighs are on the seat holds
//    the trunk where the thighs cannot reach it (the untuned desk: 979 solver calls without the
//    order, 155 with it).
#include <optional>

#include "planner/guide/guide_planner.h"
#include "planner/io/scenario.h"

namespace stanceplan {

// nullopt when the scenario's own guide is whole (nothing computed); otherwise the computed
// guide, which carries its status (a guide that failed is returned as it failed, and the
// scenario's guide is then left as it was).
std::optional<ComputedGuide> complete_scenario_guide(Scenario& scenario);

}  // namespace stanceplan
