// plot_ticks: round tick values and the labels people read on the plots' axes.
#include "app/gui/plot_ticks.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stanceplan::gui {
namespace {

TEST(PlotTicks, StepsAreOneTwoOrFiveTimesAPowerOfTen) {
  const AxisTicks t = axis_ticks(0.0, 87.0, 5, false);
  EXPECT_EQ(t.step, 20.0);
  EXPECT_EQ(t.values, (std::vector<double>{0, 20, 40, 60, 80}));
  EXPECT_EQ(axis_ticks(0.0, 1.04, 5, false).step, 0.5);
  EXPECT_EQ(axis_ticks(0.0, 0.013, 4, false).step, 0.005);
  EXPECT_EQ(axis_ticks(0.0, 4000.0, 5, false).step, 1000.0);
}

TEST(PlotTicks, TicksStayInsideTheRangeOnRoundValues) {
  const AxisTicks t = axis_ticks(3.2, 17.9, 4, false);
  ASSERT_FALSE(t.values.empty());
  EXPECT_GE(t.values.front(), 3.2);
  EXPECT_LE(t.values.back(), 17.9);
  for (double v : t.values) EXPECT_DOUBLE_EQ(v / t.step, std::round(v / t.step));
  EXPECT_LE(t.values.size(), 4u);
}

TEST(PlotTicks, WholeAxesNeverStepByFractions) {
  const AxisTicks t = axis_ticks(0.0, 3.0, 8, true);
  EXPECT_EQ(t.step, 1.0);
  EXPECT_EQ(t.values, (std::vector<double>{0, 1, 2, 3}));
  EXPECT_EQ(axis_ticks(0.0, 3.0, 8, false).step, 0.5);
}

TEST(PlotTicks, LabelsCarryTheDecimalsTheStepNeedsAndNoMore) {
  EXPECT_EQ(tick_label(40.0, 20.0), "40");
  EXPECT_EQ(tick_label(0.5, 0.5), "0.5");
  EXPECT_EQ(tick_label(1.0, 0.5), "1.0");
  EXPECT_EQ(tick_label(0.25, 0.05), "0.25");
  EXPECT_EQ(tick_label(0.0, 0.005), "0.000");
  EXPECT_EQ(tick_label(15000.0, 5000.0), "15k");
  EXPECT_EQ(tick_label(12500.0, 2500.0), "12.5k");
  EXPECT_EQ(tick_label(2e7, 1e7), "20M");
}

}  // namespace
}  // namespace stanceplan::gui
