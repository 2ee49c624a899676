#pragma once
// `stanceplan guide SCENARIO.yaml [--out guide.yaml] [--strip FILE.png] [--seed N] [--stats]`:
// computes the scenario's guide path (planner/guide/guide_planner.h) and writes it in the
// scenario's own `guide:` syntax (standard output without --out), optionally as a figure strip.
#include <iosfwd>
#include <optional>
#include <string>

namespace stanceplan::app {

struct GuideCommandOptions {
  std::string scenario;
  std::string out;    // empty: standard output
  std::string strip;  // empty: none
  std::optional<unsigned> seed;
  bool stats = false;
};

// 0 computed; 2 not (the stage that failed on `err`); throws InputError on bad input. A scenario
// with its own guide gets one computed all the same (said on `err`): the command is for looking.
int run_guide(const GuideCommandOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
