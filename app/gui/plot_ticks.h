#pragma once
// Axis ticks that people read at a glance: steps of 1, 2 or 5 times a power of ten, and labels
// with no more digits than the step needs ("0.25", "40", "1.5k"). Plain arithmetic, no drawing,
// so the plot widget's choices are testable.
#include <string>
#include <vector>

namespace stanceplan::gui {

struct AxisTicks {
  double step = 1.0;           // distance between ticks
  std::vector<double> values;  // ascending, all within [lo, hi]
};

// At most `max_ticks` (>= 2) round values covering [lo, hi]; `whole` keeps the step at 1 or more
// (event numbers and plan steps have no halves).
AxisTicks axis_ticks(double lo, double hi, int max_ticks, bool whole);

// `value` written with the decimals `step` needs; thousands and millions as "k" / "M".
std::string tick_label(double value, double step);

}  // namespace stanceplan::gui
