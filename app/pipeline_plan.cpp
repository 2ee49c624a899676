// Planning a scenario (app/pipeline.h): the search on its worker thread, the progress line or
// the event log, live snapshots, the certified plan, and the final sequence from memory.

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <functional>
#include <optional>

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <sstream>

#include "app/collision_matrix_note.h"
#include "app/exit_codes.h"
#include "app/interrupt_handler.h"
#include "app/live/event_record.h"
#include "app/live/plan_session.h"
#include "app/live/snapshot_writer.h"
#include "app/model_warnings.h"
#include "app/pipeline.h"
#include "app/plan_output.h"
#include "planner/io/request_file.h"
#include "planner/search/plan_path.h"
#include "planner/search/stance_search.h"

namespace stanceplan::app {
namespace {

// SIGINT / SIGTERM cancel the running search (its cancel flag is an atomic store, which is
// async-signal-safe); the search then stops before its next solver iteration.
std::atomic<PlanSession*> g_running{nullptr};

extern "C" void cancel_running_search(int) {
  if (PlanSession* session = g_running.load()) session->cancel_search();
}

// Cancels `session` on SIGINT / SIGTERM for the lifetime of one search.
class CancelOnSignal {
 public:
  explicit CancelOnSignal(PlanSession& session) { g_running = &session; }
  ~CancelOnSignal() { g_running = nullptr; }

 private:
  InterruptHandler handler_{cancel_running_search};
};

std::string describe(const Scene& scene, const Stance& stance) {
  std::string out = "{";
  for (const Contact& c : stance.contacts())
    out += (out.size() > 1 ? ", " : "") + scene.surfaces.id(scene.system, c.s1) + "-" +
           scene.surfaces.id(scene.system, c.s2);
  return out + "}";
}

// Takes the session's events on the calling thread, in order, until the search ends; `report`
// prints each (the search thread never waits for the terminal).
void follow(const PlanSession& session, const std::function<void(const SearchEvent&)>& report) {
  constexpr std::chrono::milliseconds kPoll{100};
  for (size_t i = 0;;) {
    if (session.wait_for_event(i, kPoll))
      report(session.event(i++));
    else if (session.finished())
      return;
  }
}

// The plan's steps as DIR/steps/step_NNN.png and DIR/strip.png, from the plan in memory.
void render_final_sequence(const Scenario& scenario, const Plan& plan, const std::string& dir,
                           std::ostream& out, std::ostream& err) {
  const render::PlanView view = plan_view(scenario, plan);
  render_figures(view, figure_options(view),
                 {(std::filesystem::path(dir) / "steps").string(),
                  (std::filesystem::path(dir) / "strip.png").string(), "", ""},
                 out, err);
}

void print_search_stats(const SearchResult& result, size_t events, std::ostream& out) {
  out << "stats: search " << std::fixed << std::setprecision(3) << result.wall_time_s << " s wall, "
      << result.solver_time_s << " s in solves, " << result.nodes_expanded << " nodes expanded, "
      << result.solver_calls << " solver calls, " << result.plan.stats.threads
      << " solver processes, " << events << " events\n";
}

void print_snapshot_stats(const SnapshotStats& s, const std::string& dir, std::ostream& out) {
  out << "stats: snapshots " << s.images << " images for " << s.events << " events in " << dir
      << ", " << std::fixed << std::setprecision(1) << s.image_ms_median
      << " ms median per image (render + PNG), " << s.backlog_at_search_end
      << " left when the search ended, drawn in " << std::setprecision(2) << s.drain_s
      << " s after it\n";
}

// One line per search event (--verbose), or the progress line on a terminal.
std::function<void(const SearchEvent&)> event_reporter(const Scenario& scenario,
                                                       const PlanOptions& options,
                                                       std::ostream& err, int& solver_calls) {
  const bool live = isatty(STDERR_FILENO) && &err == &std::cerr;
  const int milestones = static_cast<int>(scenario.milestones.size());
  return [&scenario, &err, &solver_calls, verbose = options.verbose, live,
          milestones](const SearchEvent& e) {
    if (e.kind == SearchEventKind::Candidate) ++solver_calls;
    if (verbose) {
      err << "[" << e.number << "] " << to_string(e.kind) << " node " << e.node << " "
          << describe(scenario.scene, e.stance);
      if (e.kind == SearchEventKind::Candidate)
        err << (e.candidate_case == CandidateCase::Add      ? " add "
                : e.candidate_case == CandidateCase::Remove ? " remove "
                                                            : " ")
            << to_string(e.status) << (e.accepted ? " accepted" : " rejected: " + e.message) << " ("
            << std::fixed << std::setprecision(1) << e.time_ms << " ms, " << e.iterations
            << " iterations)";
      // Which contact, from which node: the stance above is the target's.
      if (e.kind == SearchEventKind::Candidate && e.candidate_case != CandidateCase::None)
        err << " · from node " << e.parent << ": " << event_change(scenario.scene, e);
      if (e.kind == SearchEventKind::MotionFailed || skipped_milestone(e)) err << ": " << e.message;
      err << "\n";
    } else if (live) {
      err << "\rnodes " << e.nodes << "  milestone " << e.milestone << "/" << milestones
          << "  solver calls " << solver_calls << "   " << std::flush;
    }
  };
}

// plan --requests: a candidate event's request as DIR/request_NNNNN.bin.
void write_request(const SearchEvent& e, const std::string& dir) {
  if (e.kind != SearchEventKind::Candidate || !e.request) return;
  std::ostringstream name;
  name << dir << "/request_" << std::setw(5) << std::setfill('0') << e.number << ".bin";
  write_request_file(name.str(), *e.request);
}

// Runs the search to its end on the session's thread, reporting its events here; returns their
// number. SIGINT / SIGTERM cancel it.
size_t run_search(PlanSession& session, std::optional<SnapshotWriter>& snapshots,
                  const Scenario& scenario, const PlanOptions& options, std::ostream& err) {
  int solver_calls = 0;
  size_t events = 0;
  const auto print = event_reporter(scenario, options, err, solver_calls);
  {
    CancelOnSignal on_signal(session);
    // The solver workers were forked when the session was made, before any other thread.
    session.start();
    if (snapshots) snapshots->start();
    follow(session, [&](const SearchEvent& e) {
      ++events;
      print(e);
      if (!options.requests.empty()) write_request(e, options.requests);
    });
  }
  if (isatty(STDERR_FILENO) && &err == &std::cerr && !options.verbose) err << "\n";
  if (const std::exception_ptr error = session.error()) std::rethrow_exception(error);
  return events;
}

// The snapshot writer's backlog (drawn now if it fell behind), its summary and, for a written
// plan, the final sequence beside the snapshots.
void finish_snapshots(SnapshotWriter& snapshots, const Scenario& scenario, const Plan& plan,
                      int written, const PlanOptions& options, std::ostream& out,
                      std::ostream& err) {
  const SnapshotStats stats = snapshots.finish();
  out << "snapshots: " << stats.images << " images of " << stats.events << " search events in "
      << options.snapshots << " (index " << SnapshotWriter::kIndexFile << ")\n";
  if (options.stats) print_snapshot_stats(stats, options.snapshots, out);
  if (written == kExitSuccess) render_final_sequence(scenario, plan, options.snapshots, out, err);
}

// Why there is no plan: the search's status, the closest stance and the goal's.
void report_no_plan(const SearchResult& result, const Scenario& scenario, std::ostream& err) {
  err << "stanceplan: no plan found (" << to_string(result.status) << "): " << result.message
      << "\n";
  if (result.closest_node >= 0)
    err << "  closest stance to the goal: "
        << describe(scenario.scene, result.tree[result.closest_node].stance()) << "\n";
  err << "  goal stance: " << describe(scenario.scene, scenario.stance(scenario.goal_stance))
      << "\n";
  err << "  " << result.nodes_expanded << " nodes expanded, " << result.solver_calls
      << " solver calls, " << std::fixed << std::setprecision(2) << result.wall_time_s << " s\n";
  // Plans were found, each with a transition that has no motion.
  if (result.transitions_dropped > 0)
    err << "  " << result.transitions_dropped
        << " transitions of plans found had no motion and were dropped; without motion "
           "(--no-motion, or plan without --motion) the search does not check them\n";
}

}  // namespace

// --partial: the steps from the root to the node closest to the goal, marked partial in the file
// (certified like a whole plan: only its certified prefix is written).
bool write_partial_plan(const SearchResult& result, const Scenario& scenario,
                        const std::string& path, std::ostream& err) {
  if (result.closest_node < 0) {
    err << "  no partial plan: the search has no node (the initial stance was not realised)\n";
    return false;
  }
  Plan plan = plan_to_node(result.tree, result.closest_node);
  plan.stats = result.plan.stats;
  plan.partial = std::string(to_string(result.status)) + ": " + result.message;
  const size_t steps = plan.steps.size();
  if (write_certified_plan(std::move(plan), scenario, path, true, err) != kExitSuccess)
    return false;
  err << "stanceplan: wrote a PARTIAL plan to " << path << ": " << steps
      << " steps from the initial stance to the closest stance; it does not reach the goal\n";
  return true;
}

Planned plan_scenario(const PlanOptions& options, std::ostream& out, std::ostream& err) {
  const auto started = std::chrono::steady_clock::now();
  Planned planned;
  Scenario loaded = load_scenario(options.scenario);
  if (options.seed) loaded.guide.seed = *options.seed;
  // No guide: computed before the session forks its solver processes (docs/ARCHITECTURE.md).
  const std::optional<ComputedGuide> guide = complete_scenario_guide(loaded);
  planned.scenario = std::make_shared<const Scenario>(std::move(loaded));
  const Scenario& scenario = *planned.scenario;
  print_computed_collision_matrices(scenario.scene, err);
  print_model_warnings(scenario.scene, err);
  if (guide && options.stats) print_guide_stats(*guide, out);
  if (guide && guide->status != GuideStatus::Computed) {
    err << "stanceplan: no plan: " << guide->message << "\n";
    return planned;
  }
  // With motion, the search checks each transition of the plan it finds (lazy validation): the
  // plan comes with its motion, and a transition without one was replaced.
  PlanSession session(
      scenario, search_options_with_overrides(scenario, options),
      options.motion ? std::optional<MotionOptions>(MotionOptions{}) : std::nullopt);
  if (!options.requests.empty()) std::filesystem::create_directories(options.requests);
  std::optional<SnapshotWriter> snapshots;
  if (!options.snapshots.empty())
    snapshots.emplace(session, SnapshotOptions{options.snapshots, options.snapshots_rejected});
  const size_t events = run_search(session, snapshots, scenario, options, err);
  planned.result = *session.result();
  const SearchResult& result = *planned.result;
  if (options.stats) print_search_stats(result, events, out);
  const bool found = result.status == PlanStatus::Found;
  if (options.motion && found) print_motion_checks(session.motion_checks(), result, out);
  const int written =
      found ? write_certified_plan(result.plan, scenario, options.out, options.partial, err)
            : kExitFailed;
  if (written == kExitSuccess) {
    out << "wrote " << options.out << ": " << result.plan.steps.size() << " steps, "
        << result.nodes_expanded << " nodes expanded, " << result.solver_calls << " solver calls, "
        << std::fixed << std::setprecision(2) << result.wall_time_s << " s\n";
  }
  if (snapshots) finish_snapshots(*snapshots, scenario, result.plan, written, options, out, err);
  planned.code = kExitFailed;
  if (found && written != kExitSuccess) return planned;  // why: on err (write_certified_plan)
  if (!found) {
    report_no_plan(result, scenario, err);
    if (options.partial) write_partial_plan(result, scenario, options.out, err);
    return planned;
  }
  if (options.stats)
    out << "stats: total " << std::fixed << std::setprecision(3)
        << std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()
        << " s\n";
  planned.code = kExitSuccess;
  return planned;
}

}  // namespace stanceplan::app
