#pragma once
// Runs the stanceplan command line in-process and captures its output, for tests.
#include <sstream>
#include <string>
#include <vector>

#include "app/cli.h"

namespace stanceplan::test {

struct CliResult {
  int code;
  std::string out, err;
};

inline CliResult run_cli(std::vector<std::string> args) {
  args.insert(args.begin(), "stanceplan");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  std::ostringstream out, err;
  const int code = app::run_cli(static_cast<int>(argv.size()), argv.data(), out, err);
  return {code, out.str(), err.str()};
}

}  // namespace stanceplan::test
