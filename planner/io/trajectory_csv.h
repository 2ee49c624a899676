#pragma once
// A plan's trajectory as CSV, one file per robot or object (docs/PLAN_FORMAT.md, "Trajectory
// CSV"): a header row, then one row per configuration in order (step 0, the samples of the motion
// into step 1, step 1, ...), with the time at which a player at a steady speed reaches it.
#include <string>

#include "planner/plan/plan.h"
#include "planner/scene/scene.h"

namespace stanceplan {

// Columns: time_s, step (the step reached or being moved to), then for a floating robot or object
// base_x, base_y, base_z, base_qw, base_qx, base_qy, base_qz, then one column per independent
// joint by URDF name. Each step's motion lasts step_seconds, its samples evenly spaced in time.
std::string trajectory_csv(const Scene& scene, const Plan& plan, int entity, double step_seconds);

}  // namespace stanceplan
