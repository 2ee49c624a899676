#pragma once
// The independent plan checker (PLAN_FORMAT.md, "What a checker verifies"): re-checks every step
// from the plan file and the models alone. It shares the kinematics and the collision geometry
// with the planner, never the solver: torques are recomputed from point Jacobians, not from the
// solver's torque code.
#include <string>
#include <vector>

#include "planner/io/plan_reader.h"

namespace stanceplan {

struct CheckResult {
  std::string name;       // e.g. "equilibrium force"
  std::string unit;       // of worst and tolerance
  double worst = 0.0;     // the largest violation found (0 when none)
  double tolerance = 0.0;
  int step = -1;          // where the worst was found
  std::string detail;     // what, at the worst
  bool passed() const { return worst <= tolerance; }
};

struct CertifyReport {
  std::vector<CheckResult> checks;
  bool passed() const;
};

CertifyReport certify(const LoadedPlan& plan);

}  // namespace stanceplan
