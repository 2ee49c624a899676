#pragma once
// The hook between the main job and the interactive panel (app/gui/, GLFW + Dear ImGui): the
// main job calls run_panel() when a display exists and --headless is not given; app/gui/ defines
// it. (app/live/ keeps no window header: the panel is always built.)
#include <iosfwd>
#include <optional>
#include <string>

namespace stanceplan::app {

struct PanelRequest {
  std::string scenario;        // scenario file to plan (given, or the default one resolved)
  std::string out_dir;         // where the panel writes what it saves (plan, snapshots)
  std::optional<int> threads;  // --threads, when given
  bool snapshots_rejected = true;
  int exit_after_frames = 0;  // scripted runs (tests): close the window after N frames
  std::string screenshot;     // and save it as PNG after the last one
  bool motion = true;         // the motion between the steps, played by the timeline
};

// Opens the window, runs a PlanSession on `request.scenario` under the panel's control and
// returns the exit code (app/exit_codes.h) when the window closes.
int run_panel(const PanelRequest& request, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
