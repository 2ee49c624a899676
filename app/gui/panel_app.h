#pragma once
// The interactive panel: a GLFW window with a Dear ImGui user interface over a live
// stance search. The 3-D view is drawn by the same off-screen renderer as the PNGs (OSMesa, on a
// thread of its own) and shown as a texture; the search runs in an app::PlanSession on its worker
// thread and is held or stepped through the session's StepGate. The planner never knows a window
// exists. Needs a display (app::display_available); callers without one plan headless instead.
#include <iosfwd>
#include <optional>
#include <string>

namespace stanceplan::app {

struct PanelOptions {
  std::string scenario;                    // scenario file (stanceplan/scenario@1 YAML)
  std::string out_dir = "stanceplan-out";  // the plan found (plan.json) and the exports
  std::optional<int> threads;              // search overrides; default: the scenario's
  std::optional<double> time_limit;        // s
  std::optional<int> max_nodes;
  int width = 1280;  // window size in screen pixels
  int height = 720;
  bool start_paused = false;  // hold the search before its first event
  double speed_limit = 0.0;   // events per second while running; 0: no limit
  // Scripted runs (tests, README screenshots): close the window after this many frames (0: run
  // until the user closes it), write the window's pixels to `screenshot` (the last frame waits for
  // the 3-D view of what it shows, then is read back after drawing the panel), and select a node
  // as soon as it exists.
  int exit_after_frames = 0;
  bool frames_after_search = false;  // count exit_after_frames from the end of the search
  std::string screenshot;
  std::optional<int> select_node;
  // A panel script (panel_script.h): actions run in order against the live window, one line
  // printed per action; read and checked before the window opens.
  std::string script;
  // The motion between the plan's steps: the search checks it on the plan it finds and drops a
  // transition without one (the timeline plays it; plan.json is saved again with it).
  bool motion = true;
};

// Runs the panel until the window is closed (or exit_after_frames, or a script's `quit`): 0 when
// closed normally, also by SIGINT or SIGTERM (which close it as the user would), 1 when no window
// can be opened (said on `err`), 2 when a script action failed (a `wait-for plan` on a search that
// ended without one). Bad input throws InputError (file, field, expected,
// found) like every command. Closing the window cancels the search (between solver iterations)
// and joins its thread; the figures of the session (frame and render times, how long the search
// took to stop) are printed on `out`.
int run_panel(const PanelOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
