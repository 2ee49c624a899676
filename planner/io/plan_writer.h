#pragma once
// Writes a plan in exactly the format of docs/PLAN_FORMAT.md, atomically, with paths relative to
// the plan file's folder.
#include <string>

#include "planner/io/scenario.h"
#include "planner/plan/plan.h"

namespace stanceplan {

std::string plan_to_json(const Plan& plan, const Scenario& scenario, const std::string& plan_path);
void write_plan(const Plan& plan, const Scenario& scenario, const std::string& plan_path);

}  // namespace stanceplan
