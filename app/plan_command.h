#pragma once
// `stanceplan plan SCENARIO.yaml [--out plan.json] [--threads N] [--time-limit S] [--max-nodes N]`:
// runs the stance search and writes the plan (PLAN_FORMAT.md).
#include <iosfwd>
#include <optional>
#include <string>

namespace stanceplan::app {

struct PlanOptions {
  std::string scenario;
  std::string out = "plan.json";
  std::optional<int> threads;
  std::optional<double> time_limit;
  std::optional<int> max_nodes;
  bool verbose = false;
};

// 0 plan written, 2 no plan found (why and the closest stance on `err`); InputError on bad input.
int run_plan(const PlanOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
