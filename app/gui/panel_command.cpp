#include "app/gui/panel_command.h"

#include <CLI/CLI.hpp>

#include <cstdio>

namespace stanceplan::app {
namespace {

// "1280x720" -> (1280, 720) for a window between 640x400 and 7680x4320.
bool parse_window_size(const std::string& text, int* width, int* height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
    return false;
  if (w < 640 || h < 400 || w > 7680 || h > 4320) return false;
  *width = w;
  *height = h;
  return true;
}

}  // namespace

void add_panel_subcommand(CLI::App& cli, PanelOptions& options) {
  CLI::App* cmd = cli.add_subcommand(
      "panel",
      "Plan a scenario in a window (needs a display): the 3-D view, search controls "
      "(run, pause, step, next milestone, cancel), the search tree, node inspection and "
      "the plan's timeline");
  cmd->add_option("scenario", options.scenario, "scenario file (stanceplan/scenario@1 YAML)")
      ->required();
  cmd->add_option("--out", options.out_dir,
                  "folder for the plan found and the exports (default: stanceplan-out)");
  cmd->add_option("--threads", options.threads,
                  "candidate solves in parallel (default: the number of cores)")
      ->check(CLI::Range(1, 256));
  cmd->add_option("--time-limit", options.time_limit,
                  "seconds before giving up (default: the scenario's)")
      ->check(CLI::PositiveNumber);
  cmd->add_option("--max-nodes", options.max_nodes,
                  "expanded nodes before giving up (default: the scenario's)")
      ->check(CLI::Range(1, 100000000));
  cmd->add_option_function<std::string>(
         "--size",
         [&options](const std::string& text) {
           if (!parse_window_size(text, &options.width, &options.height))
             throw CLI::ValidationError(
                 "--size",
                 "expected WIDTHxHEIGHT between 640x400 and 7680x4320, found \"" + text + "\"");
         },
         "window size (default: 1280x720)")
      ->type_name("WxH");
  cmd->add_flag("--paused", options.start_paused, "hold the search before its first event");
  cmd->add_flag("!--no-motion", options.motion,
                "no motion between the plan's steps (by default the search checks the motion of "
                "each transition of the plan it finds, the timeline plays it, plan.json has it)");
  cmd->add_option("--speed-limit", options.speed_limit,
                  "events per second while running (default: no limit)")
      ->check(CLI::NonNegativeNumber);
  cmd->add_option("--exit-after-frames", options.exit_after_frames,
                  "close the window after N frames (scripted runs)")
      ->check(CLI::Range(1, 100000000));
  cmd->add_flag("--frames-after-search", options.frames_after_search,
                "count --exit-after-frames from the end of the search (scripted runs)");
  cmd->add_option("--screenshot", options.screenshot,
                  "save the window as PNG after its last frame (waits for the 3-D view)");
  cmd->add_option(
      "--script", options.script,
      "run the actions of FILE against the live window, one per line (run, pause, "
      "step event, wait 2, wait-for plan, screenshot F.png, quit, ...: docs/README.md)");
  cmd->add_option("--select-node", options.select_node,
                  "select this node as soon as the search makes it")
      ->check(CLI::NonNegativeNumber);
}

}  // namespace stanceplan::app
