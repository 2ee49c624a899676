#include "app/posture_command.h"

#include <iomanip>
#include <ostream>

#include "app/collision_matrix_note.h"
#include "app/exit_codes.h"
#include "app/model_warnings.h"
#include "app/plan_output.h"
#include "planner/io/plan_writer.h"
#include "planner/plan/plan_step.h"
#include "planner/solver/posture_solver.h"

namespace stanceplan::app {
namespace {

// `posture --out` without a posture: the solver's last iterate (the starting guess when the solve
// was refused before it began) as a one-step plan marked failed, so that it can be rendered and
// looked at; `certify` refuses it. Not written when a number of it is not finite.
void write_failed_posture(const PostureRequest& request, PostureResult result,
                          const Scenario& scenario, const std::vector<StanceContact>& contacts,
                          const PostureOptions& options, std::ostream& err) {
  if (result.q.size() != scenario.scene.system.nq()) result.q = request.q_init;
  if (const std::string part = result.non_finite_part(); !part.empty()) {
    err << "stanceplan: " << options.out << " not written: the last iterate has a non-finite "
        << part << "\n";
    return;
  }
  Plan plan;
  plan.steps.push_back(
      make_plan_step(request, result, scenario.stance(contacts), "initial", std::nullopt));
  plan.stats.solver_calls = 1;
  plan.stats.wall_time_s = result.time_ms / 1000.0;
  plan.failed = "no posture for the " + options.stance + " stance: " + to_string(result.status) +
                " (" + result.message + ")";
  write_plan(plan, scenario, options.out);
  err << "stanceplan: wrote the last iterate of the failed solve to " << options.out
      << " (marked failed: render it to look at it; certify refuses it)\n";
}

}  // namespace

int run_posture(const PostureOptions& options, std::ostream& out, std::ostream& err) {
  const Scenario scenario = load_scenario(options.scenario);
  print_computed_collision_matrices(scenario.scene, err);
  print_model_warnings(scenario.scene, err);
  const bool goal = options.stance == "goal";
  const std::vector<StanceContact>& contacts =
      goal ? scenario.goal_stance : scenario.initial_stance;
  // The goal's best guess is the last milestone (the guide path ends at q_goal).
  const PostureRequest request = scenario.loaded_request(
      contacts, goal && !scenario.milestones.empty() ? scenario.milestones.back()
                                                     : scenario.initial_configuration);
  SolverOptions solver_options = scenario.solver;
  solver_options.diagnose_infeasibility = true;
  const PostureSolver solver(scenario.scene, solver_options);
  const PostureResult result = solver.solve(request);
  if (result.status != PostureStatus::Solved) {
    err << "stanceplan: no posture for the " << options.stance << " stance of " << options.scenario
        << ": " << to_string(result.status) << " (" << result.message << ")\n";
    for (const auto& [family, residual] : result.residuals)
      err << "  " << std::left << std::setw(18) << family << " worst violation " << residual
          << "\n";
    if (!options.out.empty())
      write_failed_posture(request, result, scenario, contacts, options, err);
    return kExitFailed;
  }
  Plan plan;
  plan.steps.push_back(
      make_plan_step(request, result, scenario.stance(contacts), "initial", std::nullopt));
  plan.stats.solver_calls = 1;
  plan.stats.wall_time_s = result.time_ms / 1000.0;
  if (options.out.empty()) {
    if (!certify_in_memory(plan, scenario, err).passed()) return kExitFailed;
    out << plan_to_json(plan, scenario, "./posture.json") << "\n";
  } else {
    if (const int code = write_certified_plan(plan, scenario, options.out, false, err);
        code != kExitSuccess)
      return code;
    out << "wrote " << options.out << "\n";
  }
  err << "solved the " << options.stance << " stance in " << result.iterations << " iterations, "
      << std::fixed << std::setprecision(1) << result.time_ms << " ms\n";
  return kExitSuccess;
}

}  // namespace stanceplan::app
