#pragma once
// Options of the detour on the stance manifold (stance_rrt.h) that a motion tries when the
// straight interpolation between two configurations fails.
#include <cstdint>

namespace stanceplan {

struct StanceRrtOptions {
  // Per plan(), to find a path: the detour fails beyond. The desk's step 39 (the hands from over
  // the desk top to under its edge while the robot sits down) joins after 7980; with 2500 it
  // failed, and a step that has no motion at all (the desk's 42) spends them all, 30-40 s.
  int max_projections = 12000;
  double spread = 1.0;         // rad: the joints of a random target, around the straight path
  double step = 0.8;           // an extension's reference step, in units of the spacing
  int max_connect_steps = 60;  // extensions towards one target
  int shortcut_attempts = 40;
  int max_shortcut_projections = 300;  // the shortcuts' own budget, once a path is found
  std::uint64_t seed = 1;
};

}  // namespace stanceplan
