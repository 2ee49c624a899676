#pragma once
// A computed guide (planner/guide/guide_planner.h) written in a scenario's own `guide:` syntax
// (scenarios/README.md): one partial milestone per line, base positions in millimetres and
// orientations as base_rpy, so that a user can read it, edit it and paste it into the file.
#include <string>
#include <vector>

#include "planner/guide/guide_milestones.h"
#include "planner/model/system.h"

namespace stanceplan {

// "guide:\n  - robot: {base_position: [0.400, 0.000, 0.900]}\n..." preceded by `comment` lines
// (each written as "# ...").
std::string guide_section(const System& system, const std::vector<GuideMilestone>& milestones,
                          const std::vector<std::string>& comment = {});

}  // namespace stanceplan
