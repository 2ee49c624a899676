#include "planner/util/fork_gate.h"

#include <unistd.h>

#include <condition_variable>
#include <mutex>

namespace stanceplan {
namespace {

struct GateState {
  std::mutex mutex;
  std::condition_variable changed;
  int passes = 0;       // Pass objects alive
  bool closed = false;  // a fork in progress
};

GateState& state() {
  static GateState gate;
  return gate;
}

}  // namespace

ForkGate::Pass::Pass() {
  GateState& g = state();
  std::unique_lock<std::mutex> lock(g.mutex);
  g.changed.wait(lock, [&] { return !g.closed; });
  ++g.passes;
}

ForkGate::Pass::~Pass() {
  GateState& g = state();
  {
    std::lock_guard<std::mutex> lock(g.mutex);
    --g.passes;
  }
  g.changed.notify_all();
}

ForkGate::Closed::Closed() : owner_(getpid()) {
  GateState& g = state();
  std::unique_lock<std::mutex> lock(g.mutex);
  // Readers first: a pending fork does not stop new passes (see the header), so wait for a gap.
  g.changed.wait(lock, [&] { return g.passes == 0 && !g.closed; });
  g.closed = true;
}

ForkGate::Closed::~Closed() {
  if (getpid() != owner_) return;  // in a child forked under the gate (see the header)
  GateState& g = state();
  {
    std::lock_guard<std::mutex> lock(g.mutex);
    g.closed = false;
  }
  g.changed.notify_all();
}

}  // namespace stanceplan
