#include "app/cli.h"

#include <CLI/CLI.hpp>

#include <ostream>

#include "app/certify_command.h"
#include "app/cli_validators.h"
#include "app/gui/panel_command.h"
#include "app/guide_command.h"
#include "app/inspect_command.h"
#include "app/live/data_dir.h"
#include "app/live/main_job.h"
#include "app/motion_command.h"
#include "app/plan_command.h"
#include "app/posture_command.h"
#include "app/render_command.h"
#include "app/replay_command.h"
#include "planner/util/input_error.h"

namespace stanceplan::app {
namespace {

void add_collision_matrix_options(CLI::App& cmd, InspectOptions& options) {
  CLI::Option* matrix = cmd.add_flag(
      "--collision-matrix", options.collision_matrix,
      "print the self-collision matrix computed as MoveIt's setup assistant does (pairs adjacent, "
      "always in collision over the samples, default) instead of the description");
  matrix->excludes(cmd.get_option("--srdf"));
  cmd.add_option("--srdf-out", options.srdf_out,
                 "with --collision-matrix: write the pairs as SRDF <disable_collisions>")
      ->needs(matrix);
  cmd.add_option("--samples", options.samples,
                 "with --collision-matrix: random configurations (default 1000)")
      ->check(whole_number_in(1, 10000000))
      ->needs(matrix);
  cmd.add_option("--seed", options.seed, "with --collision-matrix: random seed (default 0)")
      ->needs(matrix);
  cmd.add_flag("--never", options.never,
               "with --collision-matrix: also disable pairs in collision in no sample (MoveIt "
               "does; unsound for postures no sample came near)")
      ->needs(matrix);
}

void add_inspect(CLI::App& cli, InspectOptions& options) {
  CLI::App* cmd = cli.add_subcommand("inspect",
                                     "Describe a URDF model: kind, joints, limits, mass, "
                                     "links, contact surfaces, collision geometry");
  cmd->add_option("model", options.urdf, "URDF file")->required();
  cmd->add_option("--surfaces", options.surfaces,
                  "surface file (stanceplan/surfaces@1 YAML), or auto: extracted from the "
                  "collision geometry");
  cmd->add_option("--srdf", options.srdf, "SRDF file with disabled collision pairs");
  cmd->add_option("--package-path", options.package_paths,
                  "directory searched for package:// URIs (repeatable; ROS_PACKAGE_PATH is "
                  "searched after these)");
  cmd->add_option("--kind", options.kind,
                  "entity kind: fixed | floating | object | environment (default: object for a "
                  "one-link model, fixed otherwise)")
      ->check(CLI::IsMember({"auto", "fixed", "floating", "object", "environment"}));
  cmd->add_flag("--json", options.json, "print one JSON object");
  cmd->add_option("--png", options.png,
                  "also draw the model and its surfaces (each named in its colour) to this PNG");
  cmd->add_option("--view", options.view, "with --png: front | side | top | three-quarter")
      ->check(CLI::IsMember({"front", "side", "top", "three-quarter"}));
  add_collision_matrix_options(*cmd, options);
}

void add_posture(CLI::App& cli, PostureOptions& options) {
  CLI::App* cmd =
      cli.add_subcommand("posture",
                         "Solve one stance of a scenario (every contact loaded) and write "
                         "it as a one-step plan. Exit 2 when no posture exists");
  cmd->add_option("scenario", options.scenario, "scenario file (stanceplan/scenario@1 YAML)")
      ->required();
  cmd->add_option("--stance", options.stance, "which stance: initial or goal")
      ->check(CLI::IsMember({"initial", "goal"}));
  cmd->add_option("--out", options.out, "plan file to write (default: standard output)");
}

void add_plan(CLI::App& cli, PlanOptions& options) {
  CLI::App* cmd =
      cli.add_subcommand("plan",
                         "Plan a scenario: a sequence of stances with transition postures. "
                         "Exit 2 when no plan is found");
  cmd->add_option("scenario", options.scenario, "scenario file (stanceplan/scenario@1 YAML)")
      ->required();
  cmd->add_option("--out", options.out, "plan file to write (default: plan.json)");
  cmd->add_option("--threads", options.threads,
                  "candidate solves in parallel (default: the number of cores)")
      ->check(whole_number_in(1, 256));
  cmd->add_option("--time-limit", options.time_limit,
                  "seconds before giving up (default: the scenario's)")
      ->check(finite_positive());
  cmd->add_option("--max-nodes", options.max_nodes,
                  "expanded nodes before giving up (default: the scenario's)")
      ->check(whole_number_in(1, 100000000));
  cmd->add_flag("--verbose", options.verbose, "print every search event on stderr");
  cmd->add_flag(
      "--partial", options.partial,
      "when no plan is found, write the steps to the stance closest to the goal as a plan marked "
      "\"partial\" (the exit code stays 2)");
  cmd->add_option(
      "--snapshots", options.snapshots,
      "draw every search event into DIR (event_NNNNN_KIND.png, events.jsonl) off the search "
      "thread, then the plan's steps (DIR/steps/) and strip (DIR/strip.png)");
  cmd->add_flag("!--no-rejected-snapshots", options.snapshots_rejected,
                "with --snapshots: list rejected candidates in events.jsonl without drawing them");
  cmd->add_flag("--stats", options.stats,
                "print timings: guide (when computed), search, solves, snapshots, total");
  cmd->add_option("--seed", options.seed,
                  "seed of the computed guide, for a scenario without a guide: section "
                  "(default: search.guide_seed, else 1)");
  cmd->add_flag("--motion", options.motion,
                "add the quasi-static motion between consecutive steps (certified sample by "
                "sample; plan format @2)");
  cmd->add_option("--requests", options.requests,
                  "write each candidate's solver request into DIR as request_NNNNN.bin (NNNNN: "
                  "its event number, as --verbose prints it), for stanceplan replay");
}

void add_replay(CLI::App& cli, ReplayOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "replay",
      "Solve one candidate's request again, alone, as the search solved it (from plan "
      "--requests): with Ipopt's iteration log, or another iteration limit. Exit 2 when not "
      "solved");
  cmd->add_option("scenario", options.scenario, "the scenario the request was planned for")
      ->required();
  cmd->add_option("request", options.request,
                  "request file (plan --requests DIR/request_NNNNN.bin)")
      ->required();
  cmd->add_option("--print-level", options.print_level,
                  "Ipopt's console output: 0 none (default), 5 one line per iteration")
      ->check(whole_number_in(0, 12));
  cmd->add_option("--max-iterations", options.max_iterations,
                  "Ipopt's iteration limit (default: the scenario's solver.max_iterations)")
      ->check(whole_number_in(1, 100000));
  cmd->add_option("--progress-budget", options.progress_budget,
                  "the progress budget's first iterations, 0 for none (default: the request's, "
                  "the search's search.progress_budget)")
      ->check(whole_number_in(0, 100000));
  cmd->add_flag("--show-request", options.show_request,
                "first print the request's contacts: fixed placements (x, y, theta in s2's "
                "frame) or free with the E25 target, loaded or not");
}

void add_guide(CLI::App& cli, GuideCommandOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "guide",
      "Compute a scenario's guide path (goal posture, collision-free path, milestones) and write "
      "it in the scenario's guide: syntax. Exit 2 when a stage fails");
  cmd->add_option("scenario", options.scenario, "scenario file (stanceplan/scenario@1 YAML)")
      ->required();
  cmd->add_option("--out", options.out, "file to write (default: standard output)");
  cmd->add_option("--strip", options.strip, "draw the milestones as a figure strip (PNG)");
  cmd->add_option("--seed", options.seed, "seed (default: search.guide_seed, else 1)");
  cmd->add_flag("--stats", options.stats,
                "print the guide's timings and its path's validity checks");
}

// The main job: `stanceplan [SCENARIO.yaml]` with no sub-command (app/live/main_job.h).
void add_main_job(CLI::App& cli, MainJobOptions& options) {
  cli.add_option("scenario", options.scenario,
                 std::string("scenario file for the main job (default: ") + kDefaultScenario +
                     " from the installed or source data folder)");
  cli.add_flag("--headless", options.headless, "main job: no window even when a display exists");
  cli.add_option("--out", options.out_dir, "main job: output folder (default: ./stanceplan-out)");
  cli.add_option("--threads", options.threads,
                 "main job: candidate solves in parallel (default: the number of cores)")
      ->check(CLI::Range(1, 256));
  cli.add_flag("!--no-rejected-snapshots", options.snapshots_rejected,
               "main job: list rejected candidates without drawing them");
  cli.add_flag("!--no-motion", options.motion,
               "main job: no motion between the steps (plan format @1; without a window, a GIF "
               "of the steps; in the panel, a timeline of the steps only)");
  cli.add_option("--exit-after-frames", options.exit_after_frames,
                 "main job with a display: close the panel after N frames (scripted runs)")
      ->check(CLI::Range(1, 100000000));
  cli.add_option("--screenshot", options.screenshot,
                 "main job with a display: save the panel's window as PNG after its last frame");
}

}  // namespace

int run_cli(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App cli{
      "stanceplan: multi-contact stance planning (Bouyarmane & Kheddar 2012).\n"
      "Exit codes: 0 success, 1 bad input or usage, 2 no plan found / check failed."};
  cli.require_subcommand(0, 1);
  MainJobOptions main_job;
  add_main_job(cli, main_job);
  InspectOptions inspect;
  add_inspect(cli, inspect);
  PostureOptions posture;
  add_posture(cli, posture);
  PlanOptions plan;
  add_plan(cli, plan);
  GuideCommandOptions guide;
  add_guide(cli, guide);
  ReplayOptions replay;
  add_replay(cli, replay);
  RenderOptions render_options;
  add_render_subcommand(cli, render_options);
  PanelOptions panel;
  add_panel_subcommand(cli, panel);
  MotionCommandOptions motion;
  add_motion_subcommand(cli, motion);
  std::string certify_plan;
  cli.add_subcommand("certify",
                     "Re-check a plan from the plan file and the models alone (never the solver). "
                     "Exit 2 when a check fails")
      ->add_option("plan", certify_plan, "plan file (stanceplan/plan@1 JSON)")
      ->required();
  try {
    cli.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    out << cli.help();
    return kExitSuccess;
  } catch (const CLI::ParseError& e) {
    err << "stanceplan: " << e.what() << "\n"
        << "Run 'stanceplan --help' for usage.\n";
    return kExitBadInput;
  }
  try {
    if (cli.got_subcommand("inspect")) return run_inspect(inspect, out, err);
    if (cli.got_subcommand("posture")) return run_posture(posture, out, err);
    if (cli.got_subcommand("plan")) return run_plan(plan, out, err);
    if (cli.got_subcommand("guide")) return run_guide(guide, out, err);
    if (cli.got_subcommand("replay")) return run_replay(replay, out, err);
    if (cli.got_subcommand("certify")) return run_certify(certify_plan, out, err);
    if (cli.got_subcommand("render")) return run_render(render_options, out, err);
    if (cli.got_subcommand("panel")) return run_panel(panel, out, err);
    if (cli.got_subcommand("motion")) return run_motion(motion, out, err);
    return run_main_job(main_job, out, err);
  } catch (const InputError& e) {
    err << "stanceplan: error: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const std::runtime_error& e) {  // e.g. an output file that cannot be written
    err << "stanceplan: error: " << e.what() << "\n";
    return kExitBadInput;
  }
  return kExitBadInput;
}

}  // namespace stanceplan::app
