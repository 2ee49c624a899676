#pragma once
// The planning problem as the search sees it (docs/METHOD.md section 2, "Problem"): the scene,
// the initial and goal stances, the guide's milestones and the solver's settings. Plain data:
// nothing here reads or writes a file (planner/io/scenario.h reads one from a scenario file).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/contact/contact.h"
#include "planner/scene/scene.h"
#include "planner/solver/posture_request.h"

namespace stanceplan {

// A contact of the initial or goal stance.
struct StanceContact {
  Contact contact;
  std::optional<Placement> placement;  // fixed placement, when the problem states one
  std::string field;                   // where a file states it, for messages:
  int line = 0;                        // "stances.initial[1]" at line 40 (0: unknown)
};

struct Problem {
  std::string file;  // the file it was read from, for messages ("" when made in code)
  Scene scene;
  Eigen::VectorXd initial_configuration;
  std::vector<StanceContact> initial_stance;
  std::vector<StanceContact> goal_stance;
  std::vector<Eigen::VectorXd> milestones;   // full configurations, partial ones completed
  std::vector<double> milestone_tolerances;  // per milestone; 0: search.milestone_tolerance
  // Per milestone: the contact pairs offered while it is the target (same patterns as
  // search.contact_pairs); empty: search.contact_pairs.
  std::vector<std::vector<std::pair<std::string, std::string>>> milestone_contact_pairs;
  // Per milestone, 1 for every entry of q the milestone states (a partial milestone constrains
  // only what it states; the rest of `milestones[i]` only completes the solver's reference).
  std::vector<Eigen::VectorXd> milestone_masks;
  SolverOptions solver;

  Stance stance(const std::vector<StanceContact>& contacts) const;
  // Whether the initial stance has a contact of the same two surfaces as c (the search's class).
  bool in_initial_stance(const Contact& c) const;
  // A solver request realising `contacts` with every one loaded at its stated placement (free
  // when none is stated), starting from and pulled towards q.
  PostureRequest loaded_request(const std::vector<StanceContact>& contacts,
                                const Eigen::VectorXd& q) const;
};

}  // namespace stanceplan
