#pragma once
// Plans leave the program certified: the checks and tolerances of `stanceplan certify`
// (planner/certify/certify.h) run on the plan in memory before it is written, in every command
// that writes one (plan, posture, the main job, the panel). `stanceplan certify` stays the
// independent reader of the file.
#include <iosfwd>
#include <string>

#include "planner/certify/certify.h"
#include "planner/io/scenario.h"
#include "planner/plan/plan.h"

namespace stanceplan::app {

// Certifies `plan` in the scenario's scene; each failed check, its step and where (e.g. the two
// links) go to `err`.
CertifyReport certify_in_memory(const Plan& plan, const Scenario& scenario, std::ostream& err);

// Certifies `plan` in the scenario's scene and writes it (atomically) to `path` when every check
// passes: kExitSuccess. A plan that fails is not written as a success: the failed checks go to
// `err` and kExitFailed is returned; with `partial`, the
// certified prefix (the steps before the first failing one) is written instead, marked partial.
int write_certified_plan(Plan plan, const Scenario& scenario, const std::string& path, bool partial,
                         std::ostream& err);

}  // namespace stanceplan::app
