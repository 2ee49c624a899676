#include "app/live/main_job.h"

#include <cstdlib>
#include <filesystem>
#include <ostream>

#include "app/exit_codes.h"
#include "app/live/data_dir.h"
#include "app/live/panel_hook.h"
#include "app/live/snapshot_writer.h"
#include "app/pipeline.h"

namespace stanceplan::app {
namespace {

namespace fs = std::filesystem;

std::string in_dir(const std::string& dir, const std::string& name) {
  return (fs::path(dir) / name).string();
}

// Plan with snapshots (the steps and the strip are drawn then), certify the file, then the
// animation.
int run_headless(const std::string& scenario, const MainJobOptions& options, std::ostream& out,
                 std::ostream& err) {
  const std::string& dir = options.out_dir;
  out << "stanceplan: planning " << scenario << " without a window; everything goes to " << dir
      << "\n";
  PlanOptions plan;
  plan.scenario = scenario;
  plan.out = in_dir(dir, "plan.json");
  plan.threads = options.threads;
  plan.snapshots = dir;
  plan.snapshots_rejected = options.snapshots_rejected;
  plan.motion = options.motion;  // the plan and its animation move between the steps
  const Planned planned = plan_scenario(plan, out, err);
  if (!planned.written()) {
    err << "stanceplan: the search snapshots and " << SnapshotWriter::kIndexFile << " are in "
        << dir << "\n";
    return planned.code;
  }
  // The file, read back by the independent checker; the animation from the plan in memory.
  if (const int code = certify_file(plan.out, out, err); code != kExitSuccess) return code;
  FigureFiles gif;
  gif.gif = in_dir(dir, "sequence.gif");
  const render::PlanView view = plan_view(*planned.scenario, planned.result->plan);
  render_figures(view, figure_options(view), gif, out, err);
  out << "main job done, in " << dir << ":\n"
      << "  plan            " << plan.out << " (certified)\n"
      << "  search events   " << in_dir(dir, SnapshotWriter::kIndexFile)
      << " and event_NNNNN_KIND.png\n"
      << "  step images     " << in_dir(dir, "steps") << "/step_NNN.png\n"
      << "  strip           " << in_dir(dir, "strip.png") << "\n"
      << "  animation       " << gif.gif << "\n";
  return kExitSuccess;
}

}  // namespace

bool display_available() {
  for (const char* name : {"DISPLAY", "WAYLAND_DISPLAY"})
    if (const char* value = std::getenv(name); value && *value) return true;
  return false;
}

int run_main_job(const MainJobOptions& options, std::ostream& out, std::ostream& err) {
  const std::string scenario =
      options.scenario.empty() ? default_scenario_path() : options.scenario;
  if (!options.headless && display_available())
    return run_panel({scenario, options.out_dir, options.threads, options.snapshots_rejected,
                      options.exit_after_frames, options.screenshot, options.motion},
                     out, err);
  return run_headless(scenario, options, out, err);
}

}  // namespace stanceplan::app
