#include "app/live/main_job.h"

#include <cstdlib>
#include <filesystem>
#include <ostream>

#include "app/certify_command.h"
#include "app/cli.h"
#include "app/live/data_dir.h"
#include "app/live/panel_hook.h"
#include "app/live/snapshot_writer.h"
#include "app/plan_command.h"
#include "app/render_command.h"

namespace stanceplan::app {
namespace {

namespace fs = std::filesystem;

std::string in_dir(const std::string& dir, const std::string& name) {
  return (fs::path(dir) / name).string();
}

// Plan with snapshots, certify, then the animation (plan_command draws the steps and the strip).
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
  if (const int code = run_plan(plan, out, err); code != kExitSuccess) {
    err << "stanceplan: the search snapshots and " << SnapshotWriter::kIndexFile << " are in "
        << dir << "\n";
    return code;
  }
  if (const int code = run_certify(plan.out, out, err); code != kExitSuccess) return code;
  RenderOptions gif;
  gif.plan = plan.out;
  gif.gif = in_dir(dir, "sequence.gif");
  run_render(gif, out, err);
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
  if (!options.headless && display_available()) {
#ifdef STANCEPLAN_HAVE_PANEL
    return run_panel({scenario, options.out_dir, options.threads, options.snapshots_rejected,
                      options.exit_after_frames, options.screenshot},
                     out, err);
#else
    err << "stanceplan: the panel is not built yet; running headless\n";
#endif
  }
  return run_headless(scenario, options, out, err);
}

}  // namespace stanceplan::app
