#pragma once
// Scenario files (`stanceplan/scenario@1`, YAML; every field is documented in
// scenarios/README.md): the entities, the initial and goal stances, the guide milestones, the
// physics, the solver weights, collision settings and the search budgets. Paths inside are
// relative to the scenario file's folder.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "planner/plan/problem.h"
#include "planner/scene/scene_builder.h"
#include "planner/search/search_options.h"

namespace stanceplan {

// A scenario file read: the problem (planner/plan/problem.h) with the search's options and what
// only the file knows (its name, description, and the entities as it names them).
struct Scenario : Problem {
  std::string name;
  std::string description;
  SceneSpec spec;  // entities with resolved paths, ignored pairs, gravity
  SearchOptions search;
};

// Throws InputError "FILE:LINE: FIELD: what was expected, what was found" on any fault, and the
// loaders' own errors (URDF, surfaces, meshes) for the files the scenario names.
Scenario load_scenario(const std::string& path);

}  // namespace stanceplan
