#include "app/motion_command.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <ostream>

#include "app/cli_validators.h"
#include "app/pipeline.h"
#include "planner/io/trajectory_csv.h"
#include "planner/util/atomic_file.h"
#include "planner/util/input_error.h"

namespace stanceplan::app {
namespace {

// The plan file's own world as a scenario for the writer: its entities and surfaces, its friction
// and cone generators. A plan file does not state the solver's other settings (collision margin,
// weights, iterations): they come from the scenario the plan names when it still loads (the motion
// projects with the settings the steps were solved with), else they are the defaults.
Scenario scenario_of(const LoadedPlan& loaded, std::ostream& err) {
  Scenario s;
  if (!loaded.scenario.empty()) {
    s.file = (std::filesystem::absolute(loaded.file).parent_path() / loaded.scenario)
                 .lexically_normal()
                 .string();
    try {
      s.solver = load_scenario(s.file).solver;
    } catch (const InputError& e) {
      err << "stanceplan: warning: the plan's scenario does not load, default solver settings ("
          << e.what() << ")\n";
    }
  }
  s.scene = loaded.scene;
  s.spec = loaded.spec;
  s.solver.friction = loaded.friction;
  s.solver.cone_generators = loaded.cone_generators;
  return s;
}

void write_csv(const Scenario& scenario, const Plan& plan, const MotionCommandOptions& options,
               std::ostream& out) {
  std::filesystem::create_directories(options.csv_dir);
  const System& system = scenario.scene.system;
  for (int e = 0; e < system.num_entities(); ++e) {
    if (system.entity(e).kind == EntityKind::Environment) continue;
    const std::string path =
        (std::filesystem::path(options.csv_dir) / (system.entity(e).name + ".csv")).string();
    write_file_atomically(path, trajectory_csv(scenario.scene, plan, e, options.step_seconds));
    out << "wrote " << path << "\n";
  }
}

}  // namespace

void add_motion_subcommand(CLI::App& cli, MotionCommandOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "motion",
      "Add the quasi-static motion between consecutive steps to a plan, certified sample by "
      "sample. Exit 2 when a step has no motion");
  cmd->add_option("plan", options.plan, "plan file (stanceplan/plan@1 or @2 JSON)")->required();
  cmd->add_option("--out", options.out, "plan file to write (default: the plan file itself)");
  cmd->add_option("--clearance", options.motion.clearance,
                  "height (m) over which a foot or hand leaves and approaches its surface along "
                  "the normal (default 0.03)")
      ->check(CLI::Range(0.0, 1.0));
  cmd->add_option("--csv", options.csv_dir,
                  "also write the trajectory of each robot and object as DIR/NAME.csv (time, "
                  "base, one column per joint)");
  cmd->add_option("--step-seconds", options.step_seconds,
                  "with --csv: seconds each step's motion lasts (default 1)")
      ->check(CLI::Range(0.01, 3600.0));
  cmd->add_flag("--stats", options.stats,
                "also a line per step: motion time, IK-statics solves and their Ipopt iterations, "
                "samples");
}

int run_motion(const MotionCommandOptions& options, std::ostream& out, std::ostream& err) {
  const LoadedPlan loaded = read_plan(options.plan);
  if (!loaded.plan.failed.empty())
    throw InputError(options.plan + ": failed: a failed solve has no motion");
  const Scenario scenario = scenario_of(loaded, err);
  Plan plan = loaded.plan;
  const bool every_step = add_plan_motion(scenario.scene, scenario.solver, options.motion, plan,
                                          out, err, options.stats);
  const std::string path = options.out.empty() ? options.plan : options.out;
  const int code = write_certified_plan(plan, scenario, path, false, err);
  if (code != kExitSuccess) return code;
  if (!options.csv_dir.empty()) write_csv(scenario, plan, options, out);
  out << "wrote " << path << " (certified, " << (every_step ? "with" : "with part of its")
      << " motion)\n";
  return every_step ? kExitSuccess : kExitFailed;
}

}  // namespace stanceplan::app
