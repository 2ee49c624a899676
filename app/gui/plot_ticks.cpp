#include "app/gui/plot_ticks.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace stanceplan::gui {
namespace {

// The 1, 2, 5 x 10^k that follows `step`.
double next_round_step(double step) {
  const double power = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
  const double m = step / power;
  return m < 1.5 ? 2.0 * power : m < 3.5 ? 5.0 * power : 10.0 * power;
}

std::vector<double> multiples_within(double lo, double hi, double step) {
  std::vector<double> values;
  const double first = std::ceil(lo / step - 1e-9) * step;
  for (double v = first; v <= hi + 1e-9 * step; v += step)
    values.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
  return values;
}

// Decimals needed to tell ticks `step` apart: 0 for 5, 1 for 0.5, 2 for 0.25 ...
int decimals_for(double step) {
  int decimals = 0;
  for (double s = step; decimals < 6 && std::abs(s - std::round(s)) > 1e-6 * std::max(1.0, s);
       s *= 10.0)
    ++decimals;
  return decimals;
}

}  // namespace

AxisTicks axis_ticks(double lo, double hi, int max_ticks, bool whole) {
  AxisTicks ticks;
  if (!std::isfinite(lo) || !std::isfinite(hi)) return ticks;
  if (hi < lo) std::swap(lo, hi);
  const double span = hi - lo > 0.0 ? hi - lo : std::max(std::abs(lo), 1.0);
  // The finest round step whose multiples inside the range are few enough: counting the
  // multiples (not span / step) lets 0..87 take 0, 20, ... 80 rather than 0, 50.
  const double finest = span / std::max(max_ticks, 2) / 10.0;
  ticks.step = std::pow(10.0, std::floor(std::log10(finest)));
  if (whole) ticks.step = std::max(ticks.step, 1.0);
  // Multiples of the step only, so that labels stay round whatever the range.
  ticks.values = multiples_within(lo, hi, ticks.step);
  while (static_cast<int>(ticks.values.size()) > std::max(max_ticks, 2)) {
    ticks.step = next_round_step(ticks.step);
    ticks.values = multiples_within(lo, hi, ticks.step);
  }
  return ticks;
}

std::string tick_label(double value, double step) {
  char text[32];
  const double size = std::max(std::abs(value), std::abs(step));
  // Past 10 000 the thousands carry the information; "12k" reads faster than "12000".
  const double scale = size >= 1e7 ? 1e6 : size >= 1e4 ? 1e3 : 1.0;
  const char* suffix = scale == 1e6 ? "M" : scale == 1e3 ? "k" : "";
  std::snprintf(text, sizeof text, "%.*f%s", decimals_for(step / scale), value / scale, suffix);
  return text;
}

}  // namespace stanceplan::gui
