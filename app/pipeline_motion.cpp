// The motion between a plan's steps (app/pipeline.h; planner/motion/): computed for a plan in
// memory, with one line of timing per plan.
#include <algorithm>
#include <iomanip>
#include <optional>
#include <ostream>

#include "app/pipeline.h"
#include "planner/motion/plan_motion.h"

namespace stanceplan::app {

bool add_plan_motion(const Scene& scene, const SolverOptions& solver, const MotionOptions& options,
                     Plan& plan, std::ostream& out, std::ostream& err) {
  const PlanMotionSummary summary = add_motion(scene, solver, options, plan);
  std::vector<double> times;
  size_t samples = 0;
  int solves = 0, iterations = 0;
  for (size_t i = 0; i < summary.steps.size(); ++i) {
    times.push_back(summary.steps[i].time_ms);
    solves += summary.steps[i].solves;
    iterations += summary.steps[i].iterations;
    if (plan.steps[i + 1].motion) samples += plan.steps[i + 1].motion->samples.size();
  }
  std::sort(times.begin(), times.end());
  const auto at = [&](double fraction) {
    return times.empty() ? 0.0 : times[size_t(fraction * double(times.size() - 1) + 0.5)];
  };
  out << "motion: " << summary.steps.size() << " steps, " << samples << " samples, " << solves
      << " solves (" << iterations << " iterations); per step median " << std::fixed
      << std::setprecision(1) << at(0.5) << " ms, p95 " << at(0.95) << " ms\n";
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

}  // namespace stanceplan::app
