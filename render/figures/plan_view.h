#pragma once
// What the figures draw: a plan in the scene it was planned in, whether the plan comes from the
// search in memory or from a plan file read back (app/pipeline.h makes both). A view: the scene
// and the plan must outlive it.
#include <string>

#include "planner/plan/plan.h"
#include "planner/scene/scene.h"

namespace stanceplan::render {

struct PlanView {
  const Scene& scene;
  const Plan& plan;
  double friction = 1.0;  // of the contacts: the friction cones drawn
  std::string name;       // for titles: the scenario file's stem
};

}  // namespace stanceplan::render
