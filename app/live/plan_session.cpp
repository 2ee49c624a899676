#include "app/live/plan_session.h"

#include <stdexcept>
#include <utility>

namespace stanceplan::app {

PlanSession::PlanSession(const Scenario& scenario, SearchOptions options,
                         std::optional<MotionOptions> motion)
    : scenario_(scenario),
      options_(std::move(options)),
      motion_(std::move(motion)),
      pool_solver_(scenario.scene, scenario.solver),
      pool_(pool_solver_, solver_processes(options_)),
      search_(make_search()) {}

std::unique_ptr<StanceSearch> PlanSession::make_search() {
  auto search = std::make_unique<StanceSearch>(scenario_, options_);
  search->set_solver_pool(&pool_);
  search->set_gate(&gate_);
  search->set_observer([this](const SearchEvent& e) { record(e); });
  if (motion_) {  // a fresh check per run: motion_checks() is the current run's
    SolverOptions solver = scenario_.solver;
    solver.cancel = search->cancel_flag();  // cancel() ends a check within a solver iteration
    motion_check_ = std::make_unique<MotionTransitionCheck>(scenario_.scene, solver, *motion_);
    search->set_transition_check(motion_check_->as_check());
  }
  return search;
}

PlanSession::~PlanSession() {
  cancel();
  if (worker_.joinable()) worker_.join();
}

void PlanSession::start() {
  if (worker_.joinable()) throw std::logic_error("PlanSession::start: already started");
  start_time_ = std::chrono::steady_clock::now();
  worker_ = std::thread([this] { run(); });
}

StepGate& PlanSession::gate() {
  return gate_;
}

void PlanSession::restart() {
  cancel();
  if (worker_.joinable()) worker_.join();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    events_.clear();
    times_s_.clear();
    result_.reset();
    error_ = nullptr;
    finished_ = false;
  }
  search_ = make_search();
  gate_.reopen();
  start();
}

void PlanSession::cancel() {
  search_->cancel();
  gate_.cancel();
}

bool PlanSession::finished() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return finished_;
}

size_t PlanSession::event_count() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return events_.size();
}

SearchEvent PlanSession::event(size_t index) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return events_.at(index);
}

double PlanSession::event_time_s(size_t index) const {
  std::lock_guard<std::mutex> lock(mutex_);
  return times_s_.at(index);
}

bool PlanSession::wait_for_event(size_t index, std::chrono::milliseconds timeout) const {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait_for(lock, timeout, [&] { return events_.size() > index || finished_; });
  return events_.size() > index;
}

bool PlanSession::wait_until_finished(std::chrono::milliseconds timeout) const {
  std::unique_lock<std::mutex> lock(mutex_);
  return changed_.wait_for(lock, timeout, [&] { return finished_; });
}

std::optional<SearchResult> PlanSession::result() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return result_;
}

std::vector<StepMotionResult> PlanSession::motion_checks() const {
  if (!finished()) throw std::logic_error("PlanSession::motion_checks: the search is running");
  return motion_check_ ? motion_check_->checked() : std::vector<StepMotionResult>{};
}

std::exception_ptr PlanSession::error() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return error_;
}

// Runs on the search thread: a copy under the lock, then wake the consumers. Never waits on them.
void PlanSession::record(const SearchEvent& event) {
  const double t =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time_).count();
  {
    std::lock_guard<std::mutex> lock(mutex_);
    events_.push_back(event);
    times_s_.push_back(t);
  }
  changed_.notify_all();
}

void PlanSession::run() {
  std::optional<SearchResult> result;
  std::exception_ptr error;
  try {
    result = search_->run();
  } catch (...) {  // rethrown by the consumer on its own thread (error())
    error = std::current_exception();
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    result_ = std::move(result);
    error_ = error;
    finished_ = true;
  }
  changed_.notify_all();
}

}  // namespace stanceplan::app
