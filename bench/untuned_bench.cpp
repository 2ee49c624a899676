// Whole plans of the untuned scenarios (scenarios/untuned/, what "untuned" means is in its
// README): the measure for making the search fast on tasks nobody tuned. Each scenario is planned
// with 1 and 2 threads; Google Benchmark reports the wall time and counters, and at the end the
// program prints one table of exact figures (steps, solver calls, calls per step, Ipopt iterations
// per call, rejected calls and their share of the solver time, wall time) and, per scenario, where
// the solver calls went. The counts are deterministic (the same with 1 and 2 threads, from commit
// to commit when the search does not change) unless the search is stopped by its time budget; the
// table marks a count that differs between repetitions. Each plan runs in a child process, so that
// a plan that aborts the process is reported as a crash. Run (about 8 min today, 4 of them the
// desk running into its 120 s budget twice):
//   nice -n 10 build/bench/untuned_bench
// and pick scenarios with --benchmark_filter=stairs (names: scenario/threads:N). With
// STANCEPLAN_BENCH_SET=paper it measures the paper's scenario files (bench/scenario_list.h, as
// written) the same way, so that a change to the search is judged on both sets with one tool;
// bench/solver_switches.h and bench/search_switches.h list the switches for experiments.
#include <benchmark/benchmark.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "bench/computed_guide.h"
#include "bench/plan_figures.h"
#include "bench/scenario_list.h"
#include "bench/search_switches.h"
#include "bench/solver_switches.h"
#include "planner/io/scenario.h"
#include "planner/search/stance_search.h"

namespace stanceplan {
namespace {

using bench::CallLog;
using bench::PlanFigures;
using bench::SearchOutcome;
using bench::SolverCall;

std::string untuned_dir() {
  return std::string(STANCEPLAN_SOURCE_DIR) + "/scenarios/untuned";
}

bool paper_set() {
  const char* set = std::getenv("STANCEPLAN_BENCH_SET");
  return set && std::string(set) == "paper";
}

std::string scenario_file(const std::string& name) {
  return paper_set() ? bench::scenario_path(name) : untuned_dir() + "/" + name + ".yaml";
}

// Every scenario file of the folder, by name, so that a new file is benchmarked without a change
// here and the order (and so the output) is stable; the paper's list with STANCEPLAN_BENCH_SET.
std::vector<std::string> untuned_names() {
  std::vector<std::string> names;
  if (paper_set()) {
    for (const std::string& name : bench::kScenarios)
      if (std::filesystem::exists(bench::scenario_path(name))) names.push_back(name);
    return names;
  }
  for (const auto& entry : std::filesystem::directory_iterator(untuned_dir()))
    if (entry.path().extension() == ".yaml") names.push_back(entry.path().stem().string());
  std::sort(names.begin(), names.end());
  return names;
}

struct Run {
  PlanFigures figures;
  std::vector<SolverCall> calls;
  int signal = 0;  // the signal that ended the planning process, 0 when it ended by itself
};
// Runs of each "scenario/threads", in the order they ran (repetitions of one benchmark).
std::map<std::string, std::vector<Run>> g_runs;
std::vector<std::string> g_order;

void set_counters(benchmark::State& state, const PlanFigures& f) {
  state.counters["found"] = f.found();
  state.counters["steps"] = f.steps;
  state.counters["solver_calls"] = f.calls;
  state.counters["calls_per_step"] = f.calls_per_step();
  state.counters["iter_median"] = f.iterations_median;
  state.counters["iter_p95"] = f.iterations_p95;
  state.counters["rejected"] = f.rejected;
  state.counters["rejected_time_share"] = f.rejected_time_share();
  state.counters["ms_per_step"] = f.ms_per_step();
}

// The child's log, one line per solver call as it happens ("call STATUS ACCEPTED ITERATIONS
// TIME_MS CHANGE..."), then "end STATUS STEPS NODES CALLS MILESTONE WALL_S" when the search ends:
// the calls before a crash are still there.
void log_call(std::FILE* out, const SolverCall& c) {
  std::fprintf(out, "call %d %d %d %.17g %s\n", int(c.status), int(c.accepted), c.iterations,
               c.time_ms, c.change.c_str());
  std::fflush(out);
}

void log_end(std::FILE* out, const SearchOutcome& o) {
  std::fprintf(out, "end %d %d %d %d %d %.17g\n", int(o.status), o.steps, o.nodes, o.calls,
               o.milestone, o.wall_time_s);
}

// In the child: plans and logs; never returns.
[[noreturn]] void plan_in_child(const Scenario& scenario, const SearchOptions& options,
                                const std::string& log_path) {
  std::FILE* out = std::fopen(log_path.c_str(), "w");
  CallLog log(scenario.scene);
  StanceSearch search(scenario, options);
  SearchObserver record = log.observer();
  search.set_observer([&](const SearchEvent& e) {
    const size_t before = log.calls().size();
    record(e);
    if (log.calls().size() > before) log_call(out, log.calls().back());
  });
  log_end(out, bench::outcome_of(search.run()));
  std::fclose(out);
  std::_Exit(0);  // no atexit handlers or static destructors of the parent's state
}

SolverCall parse_call(const std::string& line) {
  SolverCall c;
  int status = 0, accepted = 0, used = 0;
  std::sscanf(line.c_str(), "call %d %d %d %lf %n", &status, &accepted, &c.iterations, &c.time_ms,
              &used);
  c.status = static_cast<PostureStatus>(status);
  c.accepted = accepted != 0;
  c.change = line.substr(size_t(used));
  return c;
}

std::optional<SearchOutcome> parse_end(const std::string& line) {
  SearchOutcome o;
  int status = 0;
  if (std::sscanf(line.c_str(), "end %d %d %d %d %d %lf", &status, &o.steps, &o.nodes, &o.calls,
                  &o.milestone, &o.wall_time_s) != 6)
    return std::nullopt;
  o.status = static_cast<PlanStatus>(status);
  return o;
}

// The run as the child's log tells it; without an "end" line the child crashed: its calls so far.
Run read_run(const std::string& log_path, int milestones, int signal) {
  std::ifstream in(log_path);
  std::vector<SolverCall> calls;
  std::optional<SearchOutcome> outcome;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("call ", 0) == 0) calls.push_back(parse_call(line));
    if (line.rfind("end ", 0) == 0) outcome = parse_end(line);
  }
  SearchOutcome o = outcome.value_or(SearchOutcome{});
  if (!outcome) o.calls = int(calls.size());
  return {figures_of(o, calls, milestones), calls, outcome ? 0 : signal};
}

// Plans in a child process, so that a solve that aborts the process (an assertion inside FCL,
// seen with one thread, when solves run in the planning process itself) is reported as a crash
// with the calls before it instead of ending the benchmark.
Run plan_isolated(const Scenario& scenario, const SearchOptions& options) {
  char log_path[] = "/tmp/untuned_bench_XXXXXX";
  close(mkstemp(log_path));
  std::fflush(nullptr);
  const pid_t child = fork();
  if (child == 0) plan_in_child(scenario, options, log_path);
  const auto start = std::chrono::steady_clock::now();
  int wstatus = 0;
  waitpid(child, &wstatus, 0);
  Run run = read_run(log_path, int(scenario.milestones.size()),
                     WIFSIGNALED(wstatus) ? WTERMSIG(wstatus) : -1);
  std::remove(log_path);
  // A crashed child never said how long it ran: the time until it died, from here.
  if (run.signal != 0)
    run.figures.wall_time_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

void plan_untuned(benchmark::State& state, const std::string& name) {
  Scenario scenario = load_scenario(scenario_file(name));
  // The guide `plan` plans with: a coarse one completed where it leaves out the posture change.
  if (!bench::guide_as_plan_gives(scenario)) {
    state.SkipWithError("the guide failed");
    return;
  }
  bench::apply_solver_switches(scenario.solver);
  bench::apply_search_switches(scenario.search);
  SearchOptions options = scenario.search;
  options.threads = static_cast<int>(state.range(0));
  Run run;
  for (auto _ : state) run = plan_isolated(scenario, options);
  set_counters(state, run.figures);
  const std::string key = name + "/threads:" + std::to_string(options.threads);
  if (g_runs.find(key) == g_runs.end()) g_order.push_back(key);
  g_runs[key].push_back(std::move(run));
}

bool register_all() {
  for (const std::string& name : untuned_names())
    benchmark::RegisterBenchmark(name.c_str(), plan_untuned, name)
        ->ArgName("threads")
        ->Arg(1)
        ->Arg(2)
        ->Iterations(1)
        ->Unit(benchmark::kSecond)
        ->UseRealTime();
  return true;
}

double median_wall(const std::vector<Run>& runs) {
  std::vector<double> t;
  for (const Run& r : runs) t.push_back(r.figures.wall_time_s);
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

// "found", or why not and which milestone the search was aiming at when it stopped.
std::string outcome(const Run& run) {
  const PlanFigures& f = run.figures;
  if (run.signal != 0)
    return "crashed (" + std::string(strsignal(run.signal)) + ") after " + std::to_string(f.calls) +
           " calls";
  if (f.found()) return "found";
  return std::string(to_string(f.status)) + " (milestone " + std::to_string(f.milestone_targeted) +
         "/" + std::to_string(f.milestones) + ")";
}

// "12.34" of a per-step figure, or "-" without a plan (no steps to divide by).
std::string per_step(const PlanFigures& f, double value, const char* format) {
  if (!f.found()) return "-";
  char text[32];
  std::snprintf(text, sizeof text, format, value);
  return text;
}

// A table row; a count that differs between the repetitions is marked with "!".
void print_row(const std::string& key, const std::vector<Run>& runs) {
  const PlanFigures& f = runs.front().figures;
  bool same = true;
  for (const Run& r : runs) same = same && r.figures.deterministic() == f.deterministic();
  const double wall = median_wall(runs);
  std::printf("| %s | %s | %s | %d | %d | %s | %d / %d | %d (%.0f %%) | %d | %s | %.2f |%s\n",
              key.c_str(), outcome(runs.front()).c_str(), per_step(f, f.steps, "%.0f").c_str(),
              f.nodes, f.calls, per_step(f, f.calls_per_step(), "%.2f").c_str(),
              f.iterations_median, f.iterations_p95, f.rejected, 100.0 * f.rejected_time_share(),
              f.duplicates,
              per_step(f, f.steps > 0 ? 1000.0 * wall / f.steps : 0.0, "%.0f").c_str(), wall,
              same ? "" : " ! counts differ between repetitions");
}

void print_table() {
  std::printf(
      "\n| scenario | result | steps | nodes | solver calls | calls/step | Ipopt iterations per "
      "call, median / p95 | rejected calls (share of solver time) | solved, already in the tree "
      "| ms per step | wall s |\n|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const std::string& key : g_order) print_row(key, g_runs[key]);
}

struct ChangeTally {
  int calls = 0;
  int rejected = 0;
  double time_s = 0.0;
};

// Where the solver calls of one run went: the changes tried most often, with how many of their
// calls failed and their solver time.
void print_calls(const std::string& key, const std::vector<SolverCall>& calls) {
  std::map<std::string, ChangeTally> by_change;
  std::map<std::string, int> by_status;
  for (const SolverCall& c : calls) {
    ChangeTally& t = by_change[c.change];
    ++t.calls;
    t.rejected += c.status != PostureStatus::Solved;
    t.time_s += c.time_ms / 1000.0;
    ++by_status[to_string(c.status)];
  }
  std::vector<std::pair<std::string, ChangeTally>> top(by_change.begin(), by_change.end());
  std::stable_sort(top.begin(), top.end(),
                   [](const auto& a, const auto& b) { return a.second.calls > b.second.calls; });
  long iterations = 0;
  double solver_s = 0.0;
  for (const SolverCall& c : calls) iterations += c.iterations, solver_s += c.time_ms / 1000.0;
  std::printf("\n%s: %zu calls, %ld Ipopt iterations, %.2f s in the solver;", key.c_str(),
              calls.size(), iterations, solver_s);
  for (const auto& [status, n] : by_status) std::printf(" %s %d", status.c_str(), n);
  std::printf("; %zu distinct changes, the most tried:\n", by_change.size());
  for (size_t i = 0; i < std::min<size_t>(top.size(), 8); ++i)
    std::printf("  %4d calls, %4d rejected, %6.2f s  %s\n", top[i].second.calls,
                top[i].second.rejected, top[i].second.time_s, top[i].first.c_str());
}

void print_summary() {
  print_table();
  // The calls are the same with any thread count: one breakdown per scenario is enough.
  for (const std::string& key : g_order)
    if (key.find("/threads:1") != std::string::npos) print_calls(key, g_runs[key].front().calls);
}

}  // namespace
}  // namespace stanceplan

// Our own main (the archive's benchmark_main is then not linked in): the summary table is printed
// after every benchmark has run.
int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  stanceplan::register_all();
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  stanceplan::print_summary();
  return 0;
}
