#pragma once
// Checks of a problem's stances that need its models, made before any search: what the search
// could never repair is an input error naming the file, the stance entries and what is wrong, not
// a failed search.
#include "planner/plan/problem.h"

namespace stanceplan {

// Throws InputError when the fixed placements of the initial or goal stance put two links into
// each other (pinned_pairs.h: a link in a fixed-placement contact with a link that never moves
// has its pose from the placement alone), e.g. "desk.yaml:40: stances.initial[1]: the fixed
// placements of stances.initial[0] (robot/l_sole on env/floor) and stances.initial[1]
// (robot/r_sole on env/floor) put robot/l_foot and robot/r_foot 0.0200 m into each other".
// Nothing is checked without collision geometry or with collision avoidance switched off.
void check_pinned_stances(const Problem& problem);

}  // namespace stanceplan
