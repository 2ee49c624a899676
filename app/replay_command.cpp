#include "app/replay_command.h"

#include <iomanip>
#include <ostream>
#include <stdexcept>

#include "app/exit_codes.h"
#include "planner/io/request_file.h"
#include "planner/io/scenario.h"
#include "planner/solver/posture_solver.h"
#include "planner/util/input_error.h"

namespace stanceplan::app {

int run_replay(const ReplayOptions& options, std::ostream& out, std::ostream&) {
  const Scenario scenario = load_scenario(options.scenario);
  PostureRequest request = read_request_file(options.request);
  if (options.progress_budget) request.progress_budget = *options.progress_budget;
  SolverOptions solver_options = scenario.solver;  // as the search's solver (stance_search.h)
  solver_options.print_level = options.print_level;
  if (options.max_iterations) solver_options.max_iterations = *options.max_iterations;
  const PostureSolver solver(scenario.scene, solver_options);
  PostureResult result;
  try {
    result = solver.solve(request);
  } catch (const std::invalid_argument& e) {  // PostureSolver::validate: another scene's request
    throw InputError(options.request + ": does not fit " + options.scenario + ": " + e.what());
  }
  out << "replay " << options.request << ": " << to_string(result.status) << " after "
      << result.iterations << " Ipopt iterations (" << std::fixed << std::setprecision(1)
      << result.time_ms << " ms)";
  if (!result.message.empty()) out << ": " << result.message;
  out << "\n";
  return result.status == PostureStatus::Solved ? kExitSuccess : kExitFailed;
}

}  // namespace stanceplan::app
