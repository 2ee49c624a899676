#pragma once
// Counts heap allocations of the whole test process by interposing malloc (operator new and
// Eigen's dynamic matrices both end in malloc). Include in exactly one file of a test executable.
// Under AddressSanitizer or ThreadSanitizer malloc belongs to the sanitizer (memory from
// __libc_malloc freed by its free crashes): nothing is counted and the tests skip.
#include <atomic>
#include <cstddef>

#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
#define STANCEPLAN_COUNT_ALLOCATIONS 0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer) || __has_feature(thread_sanitizer)
#define STANCEPLAN_COUNT_ALLOCATIONS 0
#endif
#endif
#ifndef STANCEPLAN_COUNT_ALLOCATIONS
#define STANCEPLAN_COUNT_ALLOCATIONS 1
#endif

namespace stanceplan::test {
inline std::atomic<long> g_allocations{0};
inline long allocations() {
  return g_allocations.load();
}
inline constexpr bool kCountsAllocations = STANCEPLAN_COUNT_ALLOCATIONS;
}  // namespace stanceplan::test

#if STANCEPLAN_COUNT_ALLOCATIONS
extern "C" void* __libc_malloc(std::size_t size);

extern "C" void* malloc(std::size_t size) {
  ++stanceplan::test::g_allocations;
  return __libc_malloc(size);
}
#endif
