#pragma once
// Counts heap allocations of the whole test process by interposing malloc (operator new and
// Eigen's dynamic matrices both end in malloc). Include in exactly one file of a test executable.
#include <atomic>
#include <cstddef>

extern "C" void* __libc_malloc(std::size_t size);

namespace stanceplan::test {
inline std::atomic<long> g_allocations{0};
inline long allocations() { return g_allocations.load(); }
}  // namespace stanceplan::test

extern "C" void* malloc(std::size_t size) {
  ++stanceplan::test::g_allocations;
  return __libc_malloc(size);
}
