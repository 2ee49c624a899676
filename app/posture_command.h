#pragma once
// `stanceplan posture SCENARIO.yaml [--stance initial|goal] [--out FILE]`: solves one stance of a
// scenario with every contact loaded and writes it as a one-step plan (docs/PLAN_FORMAT.md).
#include <iosfwd>
#include <string>

namespace stanceplan::app {

struct PostureOptions {
  std::string scenario;
  std::string stance = "initial";  // initial | goal
  std::string out;                 // empty: the plan goes to standard output
};

// 0 solved, 2 not solved (the worst violated family on `err`); throws InputError on bad input.
int run_posture(const PostureOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
