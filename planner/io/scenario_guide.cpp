#include "planner/io/scenario_guide.h"

#include "planner/guide/partial_guide.h"
#include "planner/io/guide_writer.h"

namespace stanceplan {

std::optional<ComputedGuide> complete_scenario_guide(Scenario& scenario) {
  std::optional<ComputedGuide> guide;
  if (scenario.has_guide) {
    guide = complete_written_guide(scenario, scenario.guide);
  } else {
    guide = compute_guide(scenario, scenario.guide);
    if (guide->status == GuideStatus::Computed)
      read_guide_section(scenario, guide_section(scenario.scene.system, guide->milestones),
                         scenario.file + " (computed guide)");
  }
  if (guide && guide->status == GuideStatus::Computed && scenario.search.last_contacts.empty())
    scenario.search.last_contacts = guide->phases.last;
  return guide;
}

}  // namespace stanceplan
