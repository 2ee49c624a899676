#pragma once
// Errors for bad input (files, fields, values). The message always names where the fault is
// ("file:line: field: what was expected, what was found"); see docs/ARCHITECTURE.md "Conventions".
#include <stdexcept>
#include <string>

namespace stanceplan {

class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace stanceplan
