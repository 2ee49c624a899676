#pragma once
// Parallel solves in worker processes. Ipopt 3.11 with MUMPS is not thread-safe
// (docs/DEPENDENCIES.md section 1: two threads crash), so in-process solves are serialised by a
// mutex and threads give no speed-up; separate processes do. The pool forks its workers when it is
// made: its owner (the app's PlanSession) makes it before other threads start (a fork copies only
// the calling thread) and hands it to the search. Each worker holds a copy of the scene and
// answers requests over a pipe; a worker that dies yields a NumericalFailure result for its
// request and is replaced. The pool ignores SIGPIPE
// process-wide (a write to a dead worker's pipe must fail, not end the planner). Results come back
// in request order: the caller's behaviour does not depend on the number of processes.
#include <sys/types.h>
#include <atomic>
#include <string>
#include <vector>

#include "planner/solver/posture_solver.h"

namespace stanceplan {

class SolverPool {
 public:
  // processes <= 1: no worker; solve_all runs in the calling process.
  SolverPool(const PostureSolver& solver, int processes);
  ~SolverPool();
  SolverPool(const SolverPool&) = delete;
  SolverPool& operator=(const SolverPool&) = delete;

  int processes() const { return static_cast<int>(workers_.size()); }
  std::vector<pid_t> worker_pids() const;  // for tests
  // Requests whose index is not yet dispatched when `cancel` becomes true come back as
  // NumericalFailure "cancelled"; running ones stop at their next iteration.
  std::vector<PostureResult> solve_all(const std::vector<PostureRequest>& requests,
                                       const std::atomic<bool>* cancel = nullptr);

 private:
  struct Worker {
    pid_t pid = -1;
    int to_worker = -1;    // parent writes requests
    int from_worker = -1;  // parent reads results
  };
  Worker spawn();
  bool dispatch(size_t worker, const std::string& message);
  void stop(Worker& worker);

  const PostureSolver& solver_;
  std::vector<Worker> workers_;
  std::atomic<bool>* shared_cancel_ = nullptr;  // in memory shared with the workers
};

}  // namespace stanceplan
