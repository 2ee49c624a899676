#include "app/posture_command.h"

#include <iomanip>
#include <ostream>

#include "app/exit_codes.h"
#include "app/plan_output.h"
#include "planner/io/plan_writer.h"
#include "planner/plan/plan_step.h"
#include "planner/solver/posture_solver.h"

namespace stanceplan::app {

int run_posture(const PostureOptions& options, std::ostream& out, std::ostream& err) {
  const Scenario scenario = load_scenario(options.scenario);
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
