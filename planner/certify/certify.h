#pragma once
// The independent plan checker (docs/PLAN_FORMAT.md, "What a checker verifies"): re-checks every
// step from the plan file and the models alone. It shares the kinematics and the collision geometry
// with the planner, never the solver: torques are recomputed from point Jacobians, not from the
// solver's torque code.
#include <string>
#include <vector>

#include "planner/io/plan_reader.h"

namespace stanceplan {

struct CheckResult {
  std::string name;    // e.g. "equilibrium force"
  std::string unit;    // of worst and tolerance
  double worst = 0.0;  // the largest violation found (0 when none)
  double tolerance = 0.0;
  int step = -1;       // where the worst was found
  std::string detail;  // what, at the worst
  bool passed() const { return worst <= tolerance; }
};

struct CertifyReport {
  std::vector<CheckResult> checks;
  // The earliest step at which some check exceeds its tolerance (-1 when none does): the steps
  // before it are a certified plan of their own.
  int first_failed_step = -1;
  bool passed() const;
  const CheckResult* first_failure() const;  // the first failed check in report order, or null
};

// Checks a plan read from its file (`stanceplan certify`).
CertifyReport certify(const LoadedPlan& plan);
// The same checks and tolerances on a plan in memory, with the scene it was planned in and the
// friction coefficient of its contacts (what plan.json states as "friction").
CertifyReport certify(const Scene& scene, double friction, const Plan& plan);

}  // namespace stanceplan
