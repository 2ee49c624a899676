#pragma once
// fork() copies only the calling thread: a lock that another thread holds at that moment stays
// held in the child for good. glibc makes its own malloc and stdio safe across fork, but the
// allocator of GCC 12's AddressSanitizer does not (measured: 4 of 300 children of a process whose
// other thread allocates hang in SizeClassAllocator64::GetFromAllocator, none without ASan). The
// panel's solver workers hung that way under ASan. So threads that work alongside a search that
// may fork (the panel's frames, its render thread) hold a ForkGate::Pass while they work, and
// SolverPool forks inside a ForkGate::Closed: while no Pass is held. A Pass never waits for a
// pending fork, only for one in progress (microseconds), so a thread holding a Pass may wait on
// another that takes one; the price: a thread that takes passes back to back without a pause holds
// a fork off (the panel and its render thread wait between frames). Nothing is held in a child; a
// child must not take a Pass, and a Closed ends in the parent only: in the child its destructor
// does nothing (the gate's mutex may have been copied held by a thread taking a Pass, so touching
// it there would wait for good; measured: 9 of 32 runs of the fork-gate test hung that way).
#include <sys/types.h>

namespace stanceplan {

class ForkGate {
 public:
  class Pass {
   public:
    Pass();  // waits while a fork is in progress
    ~Pass();
    Pass(const Pass&) = delete;
    Pass& operator=(const Pass&) = delete;
  };
  class Closed {
   public:
    Closed();  // waits until no Pass is held; new ones wait until this is destroyed
    ~Closed();
    Closed(const Closed&) = delete;
    Closed& operator=(const Closed&) = delete;

   private:
    pid_t owner_;  // the process that closed the gate; a forked child leaves it alone
  };
};

}  // namespace stanceplan
