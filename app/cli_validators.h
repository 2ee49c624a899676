#pragma once
// Command-line value checks whose messages say what was expected and what was found (CLI11's own
// Range / PositiveNumber say "Value abc not in range" for a word and accept "nan").
#include <CLI/CLI.hpp>

#include <charconv>
#include <cmath>
#include <string>

namespace stanceplan::app {

// A whole number in [lo, hi], e.g. --threads.
inline CLI::Validator whole_number_in(long lo, long hi) {
  const std::string range = "from " + std::to_string(lo) + " to " + std::to_string(hi);
  return CLI::Validator(
      [lo, hi, range](std::string& text) -> std::string {
        long value = 0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || value < lo || value > hi)
          return "expected a whole number " + range + ", found \"" + text + "\"";
        return "";
      },
      "INT " + range);
}

// A finite number > 0, e.g. --time-limit (a NaN would disable the limit, as no time exceeds it).
inline CLI::Validator finite_positive() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        double value = 0.0;
        const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
        if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value) ||
            !(value > 0.0))
          return "expected a finite number > 0, found \"" + text + "\"";
        return "";
      },
      "NUMBER > 0");
}

}  // namespace stanceplan::app
