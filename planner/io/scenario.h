#pragma once
// Scenario files (`stanceplan/scenario@1`, YAML; every field is documented in
// scenarios/README.md): the entities, the initial and goal stances, the guide milestones, the
// physics, the solver weights, collision settings and the search budgets. Paths inside are
// relative to the scenario file's folder.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "planner/guide/guide_options.h"
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
  // The computed guide's settings (search.guide_seed, guide_spacing, guide_max_checks), used when
  // the file has no `guide:` section (planner/guide/guide_planner.h).
  GuideOptions guide;
  bool has_guide = false;  // the file has a `guide:` section
};

// Throws InputError "FILE:LINE: FIELD: what was expected, what was found" on any fault, and the
// loaders' own errors (URDF, surfaces, meshes) for the files the scenario names.
Scenario load_scenario(const std::string& path);

// Reads `text` (YAML with a `guide:` list, the scenario's syntax) as the scenario's guide, exactly
// as a `guide:` section of its file would be read: a computed guide written as text and read back
// is the guide its user could paste. Throws InputError naming `origin` on a fault.
void read_guide_section(Scenario& scenario, const std::string& text, const std::string& origin);

}  // namespace stanceplan
