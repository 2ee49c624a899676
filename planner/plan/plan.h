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

// How the motion into a step ended (docs/PLAN_FORMAT.md, `motion`): Solved when every sample is
// projected and consecutive samples are within the spacing; otherwise the samples up to the
// failure are kept, to be looked at, and `certify` refuses the step (check "motion status").
enum class MotionStatus { Solved, ProjectionFailed, SpacingNotReached, EndsDisagree };
const char* to_string(MotionStatus status);
bool parse_motion_status(const std::string& text, MotionStatus* status);

// One configuration of a motion between two steps, in static equilibrium on the contacts it
// holds (the stance of the step the motion leaves, every contact loaded).
struct MotionSample {
  Eigen::VectorXd q;
  std::vector<VertexForce> forces;       // VertexForce::contact indexes that stance's contacts()
  std::vector<Eigen::VectorXd> torques;  // per entity (empty for entities without dofs)
};

// The quasi-static path from the previous step's configuration to this step's: the samples
// strictly between the two (the steps themselves are its ends).
struct StepMotion {
  MotionStatus status = MotionStatus::Solved;
  std::string message;  // why it failed ("" when solved)
  std::vector<MotionSample> samples;
};

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
  // The motion from the previous step to this one (absent for step 0 and in plans without motion).
  std::optional<StepMotion> motion;
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
