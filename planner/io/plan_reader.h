#pragma once
// Reads a plan file (docs/PLAN_FORMAT.md) back into memory with everything needed to check or draw
// it from the file and the models alone: the entities (URDFs it names), the surfaces it lists, the
// physics it states and every step. Never calls the solver.
#include <string>
#include <utility>
#include <vector>

#include "planner/plan/plan.h"
#include "planner/scene/scene_builder.h"

namespace stanceplan {

struct LoadedPlan {
  std::string file;
  std::string scenario;  // as written in the plan (relative to the plan's folder)
  SceneSpec spec;        // entities with paths resolved against the plan's folder
  Scene scene;           // surfaces come from the plan's "surfaces" section
  double friction = 1.0;
  int cone_generators = 4;  // K of the solver that made the plan (E5; informative for a checker)
  std::vector<std::pair<LinkName, LinkName>> ignored_pairs;
  Plan plan;
};

struct PlanReadOptions {
  bool build_collision = true;  // the renderer does not need collision geometry
};

// Throws InputError naming the file and the field ("plan.json: steps[2].configuration.robot:
// missing joint \"l_knee_p\"") on any fault, and the loaders' errors for the models it names.
LoadedPlan read_plan(const std::string& path, const PlanReadOptions& options = {});

}  // namespace stanceplan
