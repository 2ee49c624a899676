#pragma once
// `stanceplan plan SCENARIO.yaml [--out plan.json] [--threads N] [--time-limit S] [--max-nodes N]
// [--snapshots DIR [--no-rejected-snapshots]] [--stats]`: runs the stance search on a worker
// thread (app/live/plan_session.h) and writes the plan (docs/PLAN_FORMAT.md).
#include <iosfwd>

#include "app/pipeline.h"  // PlanOptions

namespace stanceplan::app {

// 0 plan written, 2 no plan found (why and the closest stance on `err`); InputError on bad input.
int run_plan(const PlanOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
