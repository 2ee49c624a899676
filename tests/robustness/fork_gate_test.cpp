// ForkGate (planner/util/fork_gate.h): a fork waits until no other thread holds a Pass, a Pass
// never waits for a pending fork, and children forked under the gate while another thread
// allocates inside Passes all finish (under the ASan build a child forked while the other thread
// held an allocator lock would hang, and the test with it, until CTest's timeout).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "planner/util/fork_gate.h"

namespace stanceplan {
namespace {

TEST(ForkGate, AForkWaitsForThePassesHeld) {
  std::atomic<bool> release{false}, released{false}, closed_after_release{false};
  std::atomic<bool> holding{false};
  std::thread worker([&] {
    const ForkGate::Pass pass;
    holding = true;
    while (!release) std::this_thread::yield();
    released = true;  // just before the Pass ends
  });
  while (!holding) std::this_thread::yield();
  std::thread forker([&] {
    const ForkGate::Closed closed;
    closed_after_release = released.load();
  });
  // Give the forker every chance to get through a broken gate before the Pass ends.
  std::this_thread::sleep_for(std::chrono::milliseconds(50));
  release = true;
  forker.join();
  worker.join();
  EXPECT_TRUE(closed_after_release);
}

// A thread that holds a Pass and waits for another thread taking one (the panel waiting for its
// render thread) must not deadlock with a fork pending between them.
TEST(ForkGate, APassDoesNotWaitForAPendingFork) {
  std::atomic<bool> holding{false}, release{false}, forked{false};
  std::thread worker([&] {
    const ForkGate::Pass pass;
    holding = true;
    while (!release) std::this_thread::yield();
  });
  while (!holding) std::this_thread::yield();
  std::thread forker([&] {
    const ForkGate::Closed closed;
    forked = true;
  });
  std::this_thread::sleep_for(std::chrono::milliseconds(20));  // the fork is now pending
  {
    const ForkGate::Pass second;  // returns although a fork waits
    EXPECT_FALSE(forked);
  }
  release = true;
  forker.join();
  worker.join();
  EXPECT_TRUE(forked);
}

// The pattern of the panel: one thread allocating (small to large blocks) inside Passes, another
// forking children that allocate. Every child must exit normally.
TEST(ForkGate, ChildrenForkedUnderTheGateFinishWhileAnotherThreadAllocates) {
  std::atomic<bool> stop{false};
  std::thread allocator([&] {
    std::vector<std::string> blocks(64);
    unsigned k = 1;
    while (!stop) {
      {
        const ForkGate::Pass pass;
        for (int i = 0; i < 50; ++i) {
          k = k * 1103515245u + 12345u;
          blocks[k % 64] = std::string(16 + (k >> 8) % 300000, 'x');
        }
      }
      // Between passes (the pass released), as the panel waits between frames: a thread taking
      // passes back to back would hold a fork off indefinitely (fork_gate.h). The pass used to
      // span this pause too, so a fork got in only by winning the race between one pass and the
      // next: 0.8 s on a loaded machine, 283 s on an idle one.
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
  });
  int clean_exits = 0;
  const int forks = 20;
  for (int i = 0; i < forks; ++i) {
    pid_t pid;
    {
      const ForkGate::Closed closed;
      pid = fork();
    }
    ASSERT_GE(pid, 0);
    if (pid == 0) {
      std::vector<std::string> v;
      for (int j = 0; j < 300; ++j) v.emplace_back(16 + (j * 7919) % 300000, 'y');
      _exit(v.size() == 300 ? 0 : 3);
    }
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    clean_exits += WIFEXITED(status) && WEXITSTATUS(status) == 0;
  }
  stop = true;
  allocator.join();
  EXPECT_EQ(clean_exits, forks);
}

}  // namespace
}  // namespace stanceplan
