#pragma once
// Scenario files (`stanceplan/scenario@1`, YAML; every field is documented in
// scenarios/README.md): the entities, the initial and goal stances, the guide milestones, the
// physics, the solver weights, collision settings and the search budgets. Paths inside are
// relative to the scenario file's folder.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "planner/scene/scene_builder.h"
#include "planner/search/search_options.h"
#include "planner/solver/posture_request.h"

namespace stanceplan {

// A contact of a stance as the scenario states it.
struct StanceContact {
  Contact contact;
  std::optional<Placement> placement;  // fixed placement, when the scenario gives one
  std::string field;                   // where the file states it, for messages:
  int line = 0;                        // "stances.initial[1]" at line 40 (0: unknown)
};

struct Scenario {
  std::string file;  // as given to load_scenario
  std::string name;
  std::string description;
  SceneSpec spec;    // entities with resolved paths, ignored pairs, gravity
  Scene scene;
  Eigen::VectorXd initial_configuration;
  std::vector<StanceContact> initial_stance;
  std::vector<StanceContact> goal_stance;
  std::vector<Eigen::VectorXd> milestones;  // full configurations, partial ones completed
  std::vector<double> milestone_tolerances;  // per milestone; 0: search.milestone_tolerance
  // Per milestone: the contact pairs offered while it is the target (same patterns as
  // search.contact_pairs); empty: search.contact_pairs.
  std::vector<std::vector<std::pair<std::string, std::string>>> milestone_contact_pairs;
  // Per milestone, 1 for every entry of q the milestone states (a partial milestone constrains
  // only what it states; the rest of `milestones[i]` only completes the solver's reference).
  std::vector<Eigen::VectorXd> milestone_masks;
  SolverOptions solver;
  SearchOptions search;

  Stance stance(const std::vector<StanceContact>& contacts) const;
  // A solver request realising `contacts` with every one loaded at its stated placement (free when
  // none is stated), starting from and pulled towards q.
  PostureRequest loaded_request(const std::vector<StanceContact>& contacts, const Eigen::VectorXd& q) const;
};

// Throws InputError "FILE:LINE: FIELD: what was expected, what was found" on any fault, and the
// loaders' own errors (URDF, surfaces, meshes) for the files the scenario names.
Scenario load_scenario(const std::string& path);

}  // namespace stanceplan
