#include "app/plan_command.h"

namespace stanceplan::app {

int run_plan(const PlanOptions& options, std::ostream& out, std::ostream& err) {
  return plan_scenario(options, out, err).code;
}

}  // namespace stanceplan::app
