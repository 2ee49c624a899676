#pragma once
// `stanceplan [SCENARIO.yaml] [--headless] [--out DIR] [--threads N] [--no-rejected-snapshots]`:
// the main job. With a display (DISPLAY or WAYLAND_DISPLAY set) and no --headless it opens the
// panel (panel_hook.h). Otherwise it plans with live snapshots, certifies the plan and renders
// the final sequence, everything in DIR (default ./stanceplan-out): plan.json, events.jsonl and
// event_NNNNN_KIND.png for every search event, steps/step_NNN.png, strip.png and sequence.gif.
// Without SCENARIO it uses the default scenario (data_dir.h), found from the executable.
#include <iosfwd>
#include <optional>
#include <string>

namespace stanceplan::app {

struct MainJobOptions {
  std::string scenario;  // empty: kDefaultScenario from the data folder
  std::string out_dir = "stanceplan-out";
  bool headless = false;
  std::optional<int> threads;
  bool snapshots_rejected = true;
  bool motion = true;         // the motion between steps: in the plan and the GIF, or the panel
  int exit_after_frames = 0;  // panel: close the window after N frames (scripted runs)
  std::string screenshot;     // panel: save the window as PNG after the last frame
};

// Whether the environment names a display the panel could open a window on.
bool display_available();

// 0 plan found and certified, 2 no plan / certification failed; InputError on bad input.
int run_main_job(const MainJobOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
