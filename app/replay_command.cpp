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

namespace {

void print_placement(const char* what, const Placement& p, std::ostream& out) {
  out << " " << what << " (" << p.x << ", " << p.y << ", " << p.theta << ")";
}

// What the solver was asked: each contact, s1 on s2, with its fixed placement (x, y in s2's frame,
// theta; E10-E13) or free (case 1) with its E25 target, and whether it carries force.
void print_request(const Scene& scene, const PostureRequest& request, std::ostream& out) {
  out << std::fixed << std::setprecision(3);
  for (const ContactTask& task : request.contacts) {
    out << "contact " << scene.surfaces.id(scene.system, task.contact.s1) << " on "
        << scene.surfaces.id(scene.system, task.contact.s2) << ":"
        << (task.loaded ? " loaded" : " unloaded");
    if (task.placement)
      print_placement("placed at", *task.placement, out);
    else
      out << " free";
    if (task.placement_target) print_placement("target", *task.placement_target, out);
    if (task.standoff != 0.0) out << " standoff " << task.standoff;
    out << "\n";
  }
  out.unsetf(std::ios::floatfield);
}

}  // namespace

int run_replay(const ReplayOptions& options, std::ostream& out, std::ostream&) {
  const Scenario scenario = load_scenario(options.scenario);
  PostureRequest request = read_request_file(options.request);
  if (options.progress_budget) request.progress_budget = *options.progress_budget;
  SolverOptions solver_options = scenario.solver;  // as the search's solver (stance_search.h)
  solver_options.print_level = options.print_level;
  if (options.max_iterations) solver_options.max_iterations = *options.max_iterations;
  const PostureSolver solver(scenario.scene, solver_options);
  if (options.show_request) print_request(scenario.scene, request, out);
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
