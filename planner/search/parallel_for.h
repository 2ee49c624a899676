#pragma once
// Runs body(i) for i in [0, n) on up to `threads` threads (the caller's included). Each index runs
// exactly once; results written by index keep the caller deterministic whatever the thread count.
#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

namespace stanceplan {

template <class Body>
void parallel_for(int n, int threads, Body body) {
  std::atomic<int> next{0};
  auto work = [&] {
    for (int i = next++; i < n; i = next++) body(i);
  };
  std::vector<std::thread> pool;
  for (int k = 1; k < std::min(threads, n); ++k) pool.emplace_back(work);
  work();
  for (std::thread& t : pool) t.join();
}

}  // namespace stanceplan
