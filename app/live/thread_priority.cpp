#include "app/live/thread_priority.h"

#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <filesystem>
#include <string>
#include <system_error>

namespace stanceplan::app {
namespace {

// getpriority returns -1 both as a nice value and on error: errno tells them apart.
bool nice_of(id_t tid, int* value) {
  errno = 0;
  *value = getpriority(PRIO_PROCESS, tid);
  return errno == 0;
}

}  // namespace

BackgroundPriority::BackgroundPriority() {
  const id_t self = static_cast<id_t>(gettid());
  if (nice_of(self, &original_) && original_ < kLowest)
    lowered_ = setpriority(PRIO_PROCESS, self, kLowest) == 0;
}

void BackgroundPriority::restore() {
  if (!lowered_) return;
  lowered_ = false;
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/self/task", ec)) {
    const id_t tid = static_cast<id_t>(std::stoul(task.path().filename().string()));
    int value = 0;
    if (nice_of(tid, &value) && value == kLowest) setpriority(PRIO_PROCESS, tid, original_);
  }
}

}  // namespace stanceplan::app
