#pragma once
// A plan in memory (docs/PLAN_FORMAT.md, `stanceplan/plan@1`): the sequence of stances with their
// transition configurations, contact forces and joint torques. Step semantics (docs/METHOD.md
// section 2): step 0 realises sigma_init with every contact loaded; step i > 0 is the transition
// between sigma_{i-1} and sigma_i, touching the larger stance and loading the smaller one.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "planner/contact/contact.h"
#include "planner/solver/posture_result.h"

namespace stanceplan {

struct PlanStep {
  std::string action = "initial";  // initial | add | remove
  std::optional<Contact> changed;
  std::vector<PlanContact> contacts;  // every contact touched at this configuration
  Stance stance;                      // sigma_i
  Eigen::VectorXd q;
  std::vector<VertexForce> forces;       // VertexForce::contact indexes `contacts`
  std::vector<Eigen::VectorXd> torques;  // per entity (empty for entities without dofs)
  PostureStatus status = PostureStatus::Solved;
  int iterations = 0;
  double time_ms = 0.0;
  double objective = 0.0;
};

struct PlanStats {
  int nodes_expanded = 0;
  int solver_calls = 0;
  double wall_time_s = 0.0;
  int threads = 1;
};

struct Plan {
  std::vector<PlanStep> steps;
  PlanStats stats;
  // Empty for a plan that reaches the goal. Otherwise the plan is partial (`plan --partial`): its
  // steps lead from the initial stance to the stance closest to the goal, and this says why the
  // search stopped (e.g. "node_budget: no plan within 4 expanded nodes").
  std::string partial;
  // Empty for a plan of solved postures. Otherwise the plan records a solve that failed
  // (`posture --out` without a posture): its one step is the solver's last iterate, kept so that it
  // can be rendered and looked at, and this says why (e.g. "no posture for the initial stance:
  // infeasible (...)"). `certify` never accepts it.
  std::string failed;
};

}  // namespace stanceplan
