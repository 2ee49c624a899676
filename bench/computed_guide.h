#pragma once
// A guide-free scenario given its computed guide, as `stanceplan plan` gives it one
// (app/pipeline_guide.cpp, complete_guide): the guide read in as its `guide:` section, and the
// goal contacts that only steady the body offered last unless the file states some.
#include <string>

#include "planner/guide/guide_planner.h"
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

}  // namespace stanceplan::bench
