#include "planner/search/search_events.h"

namespace stanceplan {

const char* to_string(SearchEventKind kind) {
  switch (kind) {
    case SearchEventKind::Expansion:
      return "expansion";
    case SearchEventKind::Candidate:
      return "candidate";
    case SearchEventKind::Milestone:
      return "milestone";
    case SearchEventKind::PlanFound:
      return "plan_found";
    case SearchEventKind::Failure:
      return "failure";
    case SearchEventKind::MotionFailed:
      return "motion_failed";
  }
  return "?";
}

void StepGate::pause() {
  std::lock_guard<std::mutex> lock(mutex_);
  paused_ = true;
  budget_ = 0;
}

void StepGate::resume() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    paused_ = false;
  }
  changed_.notify_all();
}

void StepGate::step(int events) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    paused_ = true;
    budget_ += events;
  }
  changed_.notify_all();
}

void StepGate::cancel() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    cancelled_ = true;
  }
  changed_.notify_all();
}

void StepGate::reopen() {
  std::lock_guard<std::mutex> lock(mutex_);
  cancelled_ = false;
  budget_ = 0;
}

bool StepGate::paused() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return paused_ && budget_ == 0;
}

bool StepGate::pass() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return cancelled_ || !paused_ || budget_ > 0; });
  if (cancelled_) return false;
  if (paused_ && budget_ > 0) --budget_;
  return true;
}

}  // namespace stanceplan
