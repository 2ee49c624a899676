#include "planner/util/heap_tuning.h"

#include <malloc.h>

#include <mutex>

namespace stanceplan {

void keep_freed_heap_for_solvers() {
  static std::once_flag once;
  std::call_once(once, [] {
    mallopt(M_MMAP_THRESHOLD, 32 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
  });
}

}  // namespace stanceplan
