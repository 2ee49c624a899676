#pragma once
// The line a command prints on stderr for each robot whose self-collision matrix was computed
// because it has no SRDF that disables any of its pairs (planner/collision/collision_matrix.h),
// when that matrix leaves out pairs the collision model would otherwise check: the planner library
// never prints, the scene's collision model carries the matrices.
#include <iosfwd>

#include "planner/scene/scene.h"

namespace stanceplan::app {

// "stanceplan: robot: 37 self-collision pairs disabled (computed: 21 adjacent, 16 always in
// collision over 1000 samples, seed 0); write them with stanceplan inspect --collision-matrix
// --srdf-out FILE"
void print_computed_collision_matrices(const Scene& scene, std::ostream& err);

}  // namespace stanceplan::app
