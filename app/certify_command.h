#pragma once
// `stanceplan certify plan.json`: re-checks a plan from the file and the models alone (never the
// solver) and prints the worst residual of each check with its step.
#include <iosfwd>
#include <string>

namespace stanceplan::app {

// 0 when every check passes, 2 when one fails; InputError on an unreadable plan.
int run_certify(const std::string& plan, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
