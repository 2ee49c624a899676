#pragma once
// `stanceplan motion PLAN.json [--out FILE] [--clearance M] [--csv DIR]`: adds the quasi-static
// motion between consecutive steps (planner/motion/, docs/METHOD.md section 7) to an existing plan,
// certifies it sample by sample and writes it (format stanceplan/plan@2; in place without --out).
#include <iosfwd>
#include <string>

#include "planner/motion/motion_options.h"

namespace CLI {
class App;
}

namespace stanceplan::app {

struct MotionCommandOptions {
  std::string plan;
  std::string out;      // empty: PLAN.json itself
  std::string csv_dir;  // DIR/ENTITY.csv per robot or object (planner/io/trajectory_csv.h)
  double step_seconds = 1.0;
  bool stats = false;  // a line per step: time, solves, iterations, samples
  MotionOptions motion;
};

void add_motion_subcommand(CLI::App& cli, MotionCommandOptions& options);

// 0: the plan with its motion, certified, written; 2: a failed check (nothing written) or a step
// without motion (written, that step without one); InputError on an unreadable plan.
int run_motion(const MotionCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
