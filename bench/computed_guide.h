#pragma once
// A scenario given the guide `stanceplan plan` gives it (app/pipeline_guide.cpp, complete_guide).
// Guide-free: the computed guide read in as its `guide:` section, and the goal contacts that only
// steady the body offered last unless the file states some.
#include <optional>
#include <string>

#include "planner/guide/guide_planner.h"
#include "planner/guide/partial_guide.h"
#include "planner/io/guide_writer.h"
#include "planner/io/scenario.h"

namespace stanceplan::bench {

// The guide computed for `s` (from its initial configuration); when computed, read into `s`.
inline ComputedGuide use_computed_guide(Scenario& s) {
  ComputedGuide guide = compute_guide(s, s.guide);
  if (guide.status != GuideStatus::Computed) return guide;
  read_guide_section(s, guide_section(s.scene.system, guide.milestones), s.file);
  if (s.search.last_contacts.empty()) s.search.last_contacts = guide.phases.last;
  return guide;
}

// `s` given the guide `stanceplan plan` plans with: computed when it has none, else its written
// guide completed where partial (partial_guide.h). False when a guide was needed and failed.
inline bool guide_as_plan_gives(Scenario& s) {
  if (!s.has_guide) return use_computed_guide(s).status == GuideStatus::Computed;
  const std::optional<ComputedGuide> completed = complete_written_guide(s, s.guide);
  return !completed || completed->status == GuideStatus::Computed;
}

}  // namespace stanceplan::bench
