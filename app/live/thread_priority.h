#pragma once
// CPU priority for the snapshot thread: low while the search runs, so that rendering takes the
// cores only when the search leaves them idle, and normal again for the backlog after it ends.
// Linux nice values are per thread, and threads inherit the value of the thread that starts them
// (the renderer's llvmpipe threads start from the snapshot thread).
namespace stanceplan::app {

class BackgroundPriority {
 public:
  // Lowers the calling thread to the lowest priority (nice 19), remembering its value.
  BackgroundPriority();
  // Gives back the remembered value to every thread of the process still at the lowest priority
  // (the caller and the threads it started while low). Raising a priority needs CAP_SYS_NICE or
  // RLIMIT_NICE; without them the threads stay low: the backlog is drawn later, never wrong.
  void restore();

  static constexpr int kLowest = 19;

 private:
  int original_ = 0;
  bool lowered_ = false;
};

}  // namespace stanceplan::app
