#pragma once
// `stanceplan plan SCENARIO.yaml [--out plan.json] [--threads N] [--time-limit S] [--max-nodes N]
// [--snapshots DIR [--no-rejected-snapshots]] [--stats]`: runs the stance search on a worker
// thread (app/live/plan_session.h) and writes the plan (docs/PLAN_FORMAT.md).
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
  // When no plan is found: write the path from the initial stance to the stance closest to the
  // goal as a plan marked partial ("partial" in the file, a line on `err`); the exit code stays 2.
  bool partial = false;
  // Live snapshots (app/live/snapshot_writer.h): every search event as DIR/event_NNNNN_KIND.png
  // and DIR/events.jsonl, drawn off the search thread; then the plan's steps as DIR/steps/ and
  // DIR/strip.png. Empty: none.
  std::string snapshots;
  bool snapshots_rejected = true;  // false: rejected candidates are listed without an image
  bool stats = false;              // print timing figures (search, snapshots, final render)
};

// 0 plan written, 2 no plan found (why and the closest stance on `err`); InputError on bad input.
int run_plan(const PlanOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
