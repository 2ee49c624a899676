// The motion between a plan's steps (app/pipeline.h; planner/motion/): computed for a plan in
// memory, with one line of timing per plan.
#include <algorithm>
#include <iomanip>
#include <optional>
#include <ostream>

#include "app/pipeline.h"
#include "planner/motion/plan_motion.h"

namespace stanceplan::app {

namespace {

// "N steps, S samples, K solves (I iterations); per step median M ms, p95 P ms" over `results`.
void print_motion_figures(const std::vector<StepMotionResult>& results, size_t samples,
                          std::ostream& out) {
  std::vector<double> times;
  int solves = 0, iterations = 0;
  for (const StepMotionResult& r : results) {
    times.push_back(r.time_ms);
    solves += r.solves;
    iterations += r.iterations;
  }
  std::sort(times.begin(), times.end());
  const auto at = [&](double fraction) {
    return times.empty() ? 0.0 : times[size_t(fraction * double(times.size() - 1) + 0.5)];
  };
  out << results.size() << " steps, " << samples << " samples, " << solves << " solves ("
      << iterations << " iterations); per step median " << std::fixed << std::setprecision(1)
      << at(0.5) << " ms, p95 " << at(0.95) << " ms";
}

// "stats: motion into step I: T ms, K solves (N iterations), S samples" per step.
void print_step_figures(const std::vector<StepMotionResult>& results, const Plan& plan,
                        std::ostream& out) {
  for (size_t i = 0; i < results.size() && i + 1 < plan.steps.size(); ++i) {
    const StepMotionResult& r = results[i];
    const std::optional<StepMotion>& motion = plan.steps[i + 1].motion;
    out << "stats: motion into step " << i + 1 << ": " << std::fixed << std::setprecision(1)
        << r.time_ms << " ms, " << r.solves << " solves (" << r.iterations << " iterations), "
        << (motion ? motion->samples.size() : 0) << " samples, " << to_string(r.motion.status)
        << "\n";
  }
}

size_t motion_samples(const Plan& plan) {
  size_t samples = 0;
  for (const PlanStep& step : plan.steps)
    if (step.motion) samples += step.motion->samples.size();
  return samples;
}

}  // namespace

bool add_plan_motion(const Scene& scene, const SolverOptions& solver, const MotionOptions& options,
                     Plan& plan, std::ostream& out, std::ostream& err, bool stats) {
  const PlanMotionSummary summary = add_motion(scene, solver, options, plan);
  out << "motion: ";
  print_motion_figures(summary.steps, motion_samples(plan), out);
  out << "\n";
  if (stats) print_step_figures(summary.steps, plan, out);
  // A step whose motion failed keeps none: the plan stays certified, the GIF jumps there.
  for (size_t i = 1; i < plan.steps.size(); ++i) {
    std::optional<StepMotion>& motion = plan.steps[i].motion;
    if (!motion || motion->status == MotionStatus::Solved) continue;
    err << "stanceplan: warning: no motion into step " << i << " (" << to_string(motion->status)
        << ": " << motion->message << "); the step is kept without one\n";
    motion.reset();
  }
  return summary.solved();
}

void print_motion_checks(const std::vector<StepMotionResult>& checks, const SearchResult& result,
                         std::ostream& out) {
  out << "motion: ";
  print_motion_figures(checks, motion_samples(result.plan), out);
  out << "; checked during the search, " << result.transitions_dropped
      << " transitions without a motion dropped, " << std::setprecision(2) << result.check_time_s
      << " s\n";
}

}  // namespace stanceplan::app
