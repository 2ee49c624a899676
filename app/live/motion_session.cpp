#include "app/live/motion_session.h"

#include <stdexcept>
#include <utility>

#include "planner/motion/step_motion.h"

namespace stanceplan::app {

MotionSession::MotionSession(const Scene& scene, SolverOptions solver, MotionOptions options,
                             Plan plan)
    : scene_(scene),
      solver_(std::move(solver)),
      options_(std::move(options)),
      plan_(std::move(plan)) {}

MotionSession::~MotionSession() {
  cancel();
  if (worker_.joinable()) worker_.join();
}

void MotionSession::start() {
  if (worker_.joinable()) throw std::logic_error("MotionSession::start: already started");
  worker_ = std::thread([this] { run(); });
}

void MotionSession::cancel() {
  cancelled_.store(true);
}

MotionProgress MotionSession::progress() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return progress_;
}

Plan MotionSession::plan() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return plan_;
}

bool MotionSession::wait_until_finished(std::chrono::milliseconds timeout) const {
  std::unique_lock<std::mutex> lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] { return progress_.finished; });
}

// The steps are read without the lock: only this thread writes the plan, and it writes a step's
// motion only (under the lock), never the configurations the planner reads.
void MotionSession::run() {
  StepMotionPlanner planner(scene_, solver_, options_);
  const size_t steps = plan_.steps.size();
  for (size_t i = 1; i < steps && !cancelled_.load(); ++i) {
    if (plan_.steps[i].motion && plan_.steps[i].motion->status == MotionStatus::Solved) {
      std::lock_guard<std::mutex> lock(mutex_);  // checked by the search (PlanSession's motion)
      progress_.steps_done = static_cast<int>(i);
      continue;
    }
    StepMotionResult result = planner.plan(plan_.steps[i - 1], plan_.steps[i]);
    const bool solved = result.motion.status == MotionStatus::Solved;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (solved) {
        plan_.steps[i].motion = std::move(result.motion);
      } else {
        plan_.steps[i].motion.reset();
        if (progress_.steps_failed++ == 0)
          progress_.first_failure = "step " + std::to_string(i) + ": " + result.motion.message;
      }
      progress_.steps_done = static_cast<int>(i);
    }
    changed_.notify_all();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    progress_.cancelled = cancelled_.load();
    progress_.finished = true;
  }
  changed_.notify_all();
}

}  // namespace stanceplan::app
