#pragma once
// SIGINT and SIGTERM handled for a scope: `handler` runs on either (it must be
// async-signal-safe: an atomic store) and the previous handlers come back when the scope ends.
// `plan` cancels its search with it, the panel closes its window.
#include <signal.h>

namespace stanceplan::app {

class InterruptHandler {
 public:
  explicit InterruptHandler(void (*handler)(int)) {
    struct sigaction action {};
    action.sa_handler = handler;
    sigemptyset(&action.sa_mask);
    sigaction(SIGINT, &action, &previous_int_);
    sigaction(SIGTERM, &action, &previous_term_);
  }
  ~InterruptHandler() {
    sigaction(SIGINT, &previous_int_, nullptr);
    sigaction(SIGTERM, &previous_term_, nullptr);
  }
  InterruptHandler(const InterruptHandler&) = delete;
  InterruptHandler& operator=(const InterruptHandler&) = delete;

 private:
  struct sigaction previous_int_ {
  }, previous_term_{};
};

}  // namespace stanceplan::app
