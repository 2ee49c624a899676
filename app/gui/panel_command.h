#pragma once
// `stanceplan panel SCENARIO.yaml [...]`: the panel with every option of PanelOptions on the
// command line (window size, start paused, speed limit, scripted frames and screenshots). The
// main job opens the same panel with its defaults when a display exists.
#include "app/gui/panel_app.h"

namespace CLI {
class App;
}

namespace stanceplan::app {

void add_panel_subcommand(CLI::App& cli, PanelOptions& options);

}  // namespace stanceplan::app
