#pragma once
// The `stanceplan` command line, callable in-process (tests drive it without spawning).
// Exit codes (app/exit_codes.h): 0 success, 1 bad input or usage, 2 no plan found / no posture /
// certification failed.
#include <iosfwd>

#include "app/exit_codes.h"

namespace stanceplan::app {

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
