#include "planner/solver/solver_pool.h"

#include <poll.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#include "planner/solver/solver_wire.h"
#include "planner/util/fork_gate.h"

namespace stanceplan {
namespace {

bool write_all(int fd, const char* data, size_t n) {
  while (n > 0) {
    const ssize_t w = ::write(fd, data, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    data += w;
    n -= size_t(w);
  }
  return true;
}

bool read_all(int fd, char* data, size_t n) {
  while (n > 0) {
    const ssize_t r = ::read(fd, data, n);
    if (r < 0 && errno == EINTR) continue;
    if (r <= 0) return false;
    data += r;
    n -= size_t(r);
  }
  return true;
}

bool send(int fd, const std::string& message) {
  const uint64_t n = message.size();
  return write_all(fd, reinterpret_cast<const char*>(&n), sizeof n) &&
         write_all(fd, message.data(), n);
}

bool receive(int fd, std::string* message) {
  uint64_t n = 0;
  if (!read_all(fd, reinterpret_cast<char*>(&n), sizeof n)) return false;
  message->resize(n);
  return read_all(fd, message->data(), n);
}

}  // namespace

SolverPool::SolverPool(const PostureSolver& solver, int processes) : solver_(solver) {
  if (processes <= 1) return;
  // A worker that died must not take the planner with it when the pool writes to its pipe.
  signal(SIGPIPE, SIG_IGN);
  void* shared = mmap(nullptr, sizeof(std::atomic<bool>), PROT_READ | PROT_WRITE,
                      MAP_SHARED | MAP_ANONYMOUS, -1, 0);
  if (shared == MAP_FAILED) return;  // no pool: solve_all runs in this process
  shared_cancel_ = new (shared) std::atomic<bool>(false);
  for (int i = 0; i < processes; ++i) workers_.push_back(spawn());
}

std::vector<pid_t> SolverPool::worker_pids() const {
  std::vector<pid_t> pids;
  for (const Worker& w : workers_) pids.push_back(w.pid);
  return pids;
}

SolverPool::~SolverPool() {
  for (Worker& w : workers_) stop(w);
  if (shared_cancel_) munmap(shared_cancel_, sizeof(std::atomic<bool>));
}

SolverPool::Worker SolverPool::spawn() {
  int down[2], up[2];
  if (pipe(down) != 0) return {};
  if (pipe(up) != 0) {
    close(down[0]);
    close(down[1]);
    return {};
  }
  // Output still buffered in this process would be copied into the worker and written again
  // when the worker's Ipopt flushes stdout.
  std::fflush(nullptr);
  // While no other thread of ours is inside its work: under ASan a child could otherwise inherit
  // an allocator lock held for good (planner/util/fork_gate.h).
  const ForkGate::Closed no_other_work;
  const pid_t pid = fork();
  if (pid == 0) {  // the worker: answer requests until the parent closes the pipe
    close(down[1]);
    close(up[0]);
    for (const Worker& other : workers_) {
      close(other.to_worker);
      close(other.from_worker);
    }
    SolverOptions options = solver_.options();
    options.cancel = shared_cancel_;
    const PostureSolver solver(solver_.scene(), options);
    std::string message;
    while (receive(down[0], &message)) {
      PostureResult result;
      try {
        result = solver.solve(deserialize_request(message));
      } catch (const std::exception& e) {
        result = PostureResult::numerical_failure(std::string("solver process: ") + e.what());
      }
      if (!send(up[1], serialize(result))) break;
    }
    _exit(0);
  }
  close(down[0]);
  close(up[1]);
  if (pid < 0) {
    close(down[1]);
    close(up[0]);
    return {};
  }
  return {pid, down[1], up[0]};
}

// Sends a request to worker w, replacing it (once) when it has died.
bool SolverPool::dispatch(size_t w, const std::string& message) {
  for (int attempt = 0; attempt < 2; ++attempt) {
    if (workers_[w].pid <= 0) workers_[w] = spawn();
    if (workers_[w].pid > 0 && send(workers_[w].to_worker, message)) return true;
    stop(workers_[w]);
  }
  return false;
}

void SolverPool::stop(Worker& w) {
  if (w.pid <= 0) return;
  close(w.to_worker);
  close(w.from_worker);
  int status = 0;
  waitpid(w.pid, &status, 0);
  w = {};
}

std::vector<PostureResult> SolverPool::solve_all(const std::vector<PostureRequest>& requests,
                                                 const std::atomic<bool>* cancel) {
  std::vector<PostureResult> results(requests.size());
  const auto cancelled = [&] { return cancel && cancel->load(); };
  if (workers_.empty()) {  // a solve asked after the cancel returns at once; a running one stops
    for (size_t i = 0; i < requests.size(); ++i)
      results[i] = cancel ? solver_.solve(requests[i], cancel) : solver_.solve(requests[i]);
    return results;
  }
  shared_cancel_->store(false);
  // Validate in the parent, where a malformed request throws as it would in-process.
  for (const PostureRequest& r : requests) solver_.validate_request(r);
  std::vector<int> busy(workers_.size(), -1);  // request index per worker
  size_t next = 0, done = 0;
  while (done < requests.size()) {
    for (size_t w = 0; w < workers_.size(); ++w) {
      if (busy[w] >= 0 || next >= requests.size()) continue;
      if (cancelled()) {
        results[next++] = PostureResult::numerical_failure("cancelled");
        ++done;
        continue;
      }
      if (dispatch(w, serialize(requests[next]))) {
        busy[w] = int(next++);
      } else {
        results[next++] = PostureResult::numerical_failure("no solver process could be started");
        ++done;
      }
    }
    if (done >= requests.size()) break;
    std::vector<pollfd> fds;
    std::vector<size_t> owners;
    for (size_t w = 0; w < workers_.size(); ++w)
      if (busy[w] >= 0) {
        fds.push_back({workers_[w].from_worker, POLLIN, 0});
        owners.push_back(w);
      }
    if (fds.empty()) continue;
    if (poll(fds.data(), fds.size(), 50) < 0 && errno != EINTR) break;
    if (cancelled()) shared_cancel_->store(true);
    for (size_t k = 0; k < fds.size(); ++k) {
      if (!(fds[k].revents & (POLLIN | POLLHUP | POLLERR))) continue;
      const size_t w = owners[k];
      std::string message;
      if (receive(workers_[w].from_worker, &message)) {
        results[busy[w]] = deserialize_result(message);
      } else {
        results[busy[w]] = PostureResult::numerical_failure("the solver process died");
        stop(workers_[w]);
      }
      busy[w] = -1;
      ++done;
    }
  }
  return results;
}

}  // namespace stanceplan
