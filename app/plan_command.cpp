#include "app/plan_command.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>

#include <cstdio>
#include <iomanip>
#include <iostream>
#include <ostream>
#include <sstream>

#include "app/cli.h"
#include "planner/io/plan_writer.h"
#include "planner/search/stance_search.h"

namespace stanceplan::app {
namespace {

// SIGINT / SIGTERM cancel the running search (its cancel flag is an atomic store, which is
// async-signal-safe); the search then stops before its next solver iteration.
std::atomic<StanceSearch*> g_running{nullptr};

extern "C" void cancel_running_search(int) {
  if (StanceSearch* search = g_running.load()) search->cancel();
}

// Installs the handlers for the lifetime of one search, restoring the previous ones after.
class CancelOnSignal {
 public:
  explicit CancelOnSignal(StanceSearch& search) {
    g_running = &search;
    struct sigaction action {};
    action.sa_handler = cancel_running_search;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_int_);
    sigaction(SIGTERM, &action, &previous_term_);
  }
  ~CancelOnSignal() {
    sigaction(SIGINT, &previous_int_, nullptr);
    sigaction(SIGTERM, &previous_term_, nullptr);
    g_running = nullptr;
  }

 private:
  struct sigaction previous_int_ {}, previous_term_ {};
};

std::string describe(const Scene& scene, const Stance& stance) {
  std::string out = "{";
  for (const Contact& c : stance.contacts())
    out += (out.size() > 1 ? ", " : "") + scene.surfaces.id(scene.system, c.s1) + "-" + scene.surfaces.id(scene.system, c.s2);
  return out + "}";
}

}  // namespace

int run_plan(const PlanOptions& options, std::ostream& out, std::ostream& err) {
  const Scenario scenario = load_scenario(options.scenario);
  SearchOptions search = scenario.search;
  if (options.threads) search.threads = *options.threads;
  if (options.time_limit) search.time_limit_s = *options.time_limit;
  if (options.max_nodes) search.max_nodes = *options.max_nodes;
  StanceSearch planner(scenario, search);
  const bool live = isatty(STDERR_FILENO) && &err == &std::cerr;
  const int milestones = static_cast<int>(scenario.milestones.size());
  int solver_calls = 0, max_depth = 0;
  planner.set_observer([&](const SearchEvent& e) {
    if (e.kind == SearchEventKind::Candidate) ++solver_calls;
    if (options.verbose) {
      err << "[" << e.number << "] " << to_string(e.kind) << " node " << e.node << " " << describe(scenario.scene, e.stance);
      if (e.kind == SearchEventKind::Candidate)
        err << (e.candidate_case == CandidateCase::Add ? " add " : e.candidate_case == CandidateCase::Remove ? " remove " : " ")
            << to_string(e.status) << (e.accepted ? " accepted" : " rejected: " + e.message) << " (" << std::fixed
            << std::setprecision(1) << e.time_ms << " ms)";
      err << "\n";
    } else if (live) {
      (void)max_depth;
      err << "\rnodes " << e.nodes << "  milestone " << e.milestone << "/" << milestones << "  solver calls "
          << solver_calls << "   " << std::flush;
    }
  });
  const SearchResult result = [&] {
    CancelOnSignal on_signal(planner);
    return planner.run();
  }();
  if (live && !options.verbose) err << "\n";
  if (result.status != PlanStatus::Found) {
    err << "stanceplan: no plan found (" << to_string(result.status) << "): " << result.message << "\n";
    if (result.closest_node >= 0)
      err << "  closest stance to the goal: " << describe(scenario.scene, result.tree[result.closest_node].stance()) << "\n";
    err << "  goal stance: " << describe(scenario.scene, scenario.stance(scenario.goal_stance)) << "\n";
    err << "  " << result.nodes_expanded << " nodes expanded, " << result.solver_calls << " solver calls, "
        << std::fixed << std::setprecision(2) << result.wall_time_s << " s\n";
    return kExitFailed;
  }
  write_plan(result.plan, scenario, options.out);
  out << "wrote " << options.out << ": " << result.plan.steps.size() << " steps, " << result.nodes_expanded
      << " nodes expanded, " << result.solver_calls << " solver calls, " << std::fixed << std::setprecision(2)
      << result.wall_time_s << " s\n";
  return kExitSuccess;
}

}  // namespace stanceplan::app
