#pragma once
// The steps the commands share, so that no command calls another (docs/ARCHITECTURE.md): plan a
// scenario on a worker thread and write the certified plan (pipeline_plan.cpp), draw a plan's
// steps, strip and GIF from a plan in memory or read back (pipeline_figures.cpp), and certify a
// plan file (pipeline_certify.cpp). `plan`, `render`, `certify` and the main job are each a few
// lines over these.
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>

#include "app/exit_codes.h"
#include "app/plan_output.h"
#include "planner/guide/guide_planner.h"
#include "planner/io/plan_reader.h"
#include "planner/io/scenario.h"
#include "planner/io/scenario_guide.h"
#include "planner/motion/motion_options.h"
#include "planner/motion/step_motion.h"
#include "planner/search/stance_search.h"
#include "render/figures/plan_view.h"
#include "render/figures/sequence.h"
#include "render/scene/mesh_library.h"

namespace stanceplan::app {

// --- planning (pipeline_plan.cpp)
struct PlanOptions {
  std::string scenario;
  std::string out = "plan.json";
  std::optional<int> threads;
  std::optional<double> time_limit;
  std::optional<int> max_nodes;
  bool verbose = false;
  // When no plan is found: write the path from the initial stance to the stance closest to the
  // goal as a plan marked partial ("partial" in the file, a line on `err`); the exit code stays 2.
  bool partial = false;
  // Live snapshots (app/live/snapshot_writer.h): every search event as DIR/event_NNNNN_KIND.png
  // and DIR/events.jsonl, drawn off the search thread; then the plan's steps as DIR/steps/ and
  // DIR/strip.png. Empty: none.
  std::string snapshots;
  bool snapshots_rejected = true;  // false: rejected candidates are listed without an image
  bool stats = false;              // print timing figures (search, snapshots, final render)
  std::optional<unsigned> seed;    // the computed guide's seed (default: search.guide_seed)
  // The motion between consecutive steps (planner/motion/) in the plan written: plan --motion.
  bool motion = false;
  // Each candidate's solver request as DIR/request_NNNNN.bin, NNNNN its event number
  // (planner/io/request_file.h; stanceplan replay). Empty: none.
  std::string requests;
};

// A scenario planned: the exit code (0: a certified plan written to PlanOptions::out; 2: no plan,
// or one that failed certification), the scenario and, when the search ran, its result.
struct Planned {
  int code = kExitFailed;
  std::shared_ptr<const Scenario> scenario;
  std::optional<SearchResult> result;
  bool written() const { return code == kExitSuccess; }
};
// Throws InputError on bad input (the scenario file, a stance placed into itself).
Planned plan_scenario(const PlanOptions& options, std::ostream& out, std::ostream& err);

// The scenario's search options with a command's overrides (its optional `threads`, `time_limit`
// and `max_nodes`: `plan`, the main job, the panel).
template <class CommandOptions>
SearchOptions search_options_with_overrides(const Scenario& scenario,
                                            const CommandOptions& options) {
  SearchOptions search = scenario.search;
  if (options.threads) search.threads = *options.threads;
  if (options.time_limit) search.time_limit_s = *options.time_limit;
  if (options.max_nodes) search.max_nodes = *options.max_nodes;
  return search;
}
// A search that ended without a plan: the steps from the root to the node closest to the goal,
// marked partial and certified like a whole plan (only its certified prefix is written), at
// `path`. False (said on `err`) when nothing was written.
bool write_partial_plan(const SearchResult& result, const Scenario& scenario,
                        const std::string& path, std::ostream& err);

// --- the computed guide (pipeline_guide.cpp)
// The guide in the scenario's `guide:` syntax, with a comment line saying how it was computed.
std::string computed_guide_text(const Scenario& scenario, const ComputedGuide& guide);
// What milestone k of a computed guide offers, for its figure: "walks on robot/l_sole on env/floor,
// ..." (an approach's milestone), else "offers robot/*_sole on env/floor, ...; last: ...".
std::string milestone_offer(const Scenario& scenario, const ComputedGuide& guide, size_t k);
// "stats: guide ..." (guide time apart from the search's).
void print_guide_stats(const ComputedGuide& guide, std::ostream& out);
// The initial configuration and every milestone's configuration as a figure strip (PNG).
void write_guide_strip(const Scenario& scenario, const ComputedGuide& guide,
                       const std::string& path, std::ostream& out, std::ostream& err);
// --- motion (pipeline_motion.cpp)
// Adds the motion between consecutive steps to `plan` and prints its timing on `out` (one line).
// A step whose motion fails keeps none, with a warning on `err` naming it and why: false then.
// `stats`: also a line per step (time, solves, Ipopt iterations, samples).
bool add_plan_motion(const Scene& scene, const SolverOptions& solver, const MotionOptions& options,
                     Plan& plan, std::ostream& out, std::ostream& err, bool stats = false);
// The motion's line for a search that checked its transitions (PlanSession with motion): every
// check's figures (the dropped transitions' too), the samples of the plan found.
void print_motion_checks(const std::vector<StepMotionResult>& checks, const SearchResult& result,
                         std::ostream& out);

// --- figures (pipeline_figures.cpp)
// The figures' view of a plan read from its file (named after its scenario file, else itself) or
// of a plan in memory with the scenario it was planned in.
render::PlanView plan_view(const LoadedPlan& loaded);
render::PlanView plan_view(const Scenario& scenario, const Plan& plan);

// The default look of the figures for a plan (1280 x 720, three-quarter view, its friction).
render::SequenceOptions figure_options(const render::PlanView& plan);

// What to draw; an empty name draws nothing of that kind.
struct FigureFiles {
  std::string steps_dir;  // DIR/step_000.png, ...
  std::string strip;      // the figure strip (PNG)
  std::string gif;        // an animated GIF of the steps
  std::string video;      // a video (MP4) of the steps, at full size (render/image/video_file.h)
  // A plan with motion plays it at a steady speed: this many frames a second, each step's motion
  // (from the previous step) lasting step_seconds (the video holds steps without one as long).
  double fps = 10.0;
  double step_seconds = 1.0;
};
// Draws the files (one mesh library for all: each mesh file read once, each warning printed
// once); says what it wrote on `out`, missing meshes on `err`.
void render_figures(const render::PlanView& plan, const render::SequenceOptions& options,
                    const FigureFiles& files, std::ostream& out, std::ostream& err);

// --- certification (pipeline_certify.cpp)
// `stanceplan certify`: reads the plan file back and re-checks it from the file and the models
// alone; prints the worst residual of each check. kExitSuccess when every check passes, else
// kExitFailed; InputError on an unreadable plan.
int certify_file(const std::string& path, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
