// The main job's way into the panel (app/live/panel_hook.h): `stanceplan [SCENARIO.yaml]` with a
// display opens the panel through this function.
#include "app/live/panel_hook.h"

#include "app/gui/panel_app.h"

namespace stanceplan::app {

int run_panel(const PanelRequest& request, std::ostream& out, std::ostream& err) {
  PanelOptions options;
  options.scenario = request.scenario;
  options.out_dir = request.out_dir;
  options.threads = request.threads;
  options.exit_after_frames = request.exit_after_frames;
  options.screenshot = request.screenshot;
  options.motion = request.motion;
  return run_panel(options, out, err);
}

}  // namespace stanceplan::app
