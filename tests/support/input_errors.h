#pragma once
// The message of the InputError a piece of code throws, for tests that assert exact messages.
#include <string>

#include "planner/util/input_error.h"

namespace stanceplan::test {

// The message of the InputError that f throws ("" when it throws none).
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace stanceplan::test
