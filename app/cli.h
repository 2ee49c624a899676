#pragma once
// The `stanceplan` command line, callable in-process (tests drive it without spawning).
// Exit codes: 0 success, 1 bad input or usage, 2 no plan found / certification failed.
#include <iosfwd>

namespace stanceplan::app {

enum ExitCode { kExitSuccess = 0, kExitBadInput = 1, kExitFailed = 2 };

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
