// The panel's layout: the view, the bar and the right column tile the window without overlap.
#include "app/gui/panel_layout.h"

#include <gtest/gtest.h>

namespace stanceplan::gui {
namespace {

float area(const Rect& r) {
  return r.w * r.h;
}

bool overlap(const Rect& a, const Rect& b) {
  return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

TEST(PanelLayout, TilesTheWindow) {
  for (const auto& [w, h] : {std::pair{1280.0f, 720.0f}, {1920.0f, 1080.0f}, {640.0f, 400.0f}}) {
    const PanelLayout l = panel_layout(w, h);
    const Rect parts[] = {l.view, l.bar, l.search, l.inspector};
    float sum = 0.0f;
    for (int i = 0; i < 4; ++i) {
      sum += area(parts[i]);
      EXPECT_GE(parts[i].x, 0.0f);
      EXPECT_LE(parts[i].x + parts[i].w, w);
      EXPECT_LE(parts[i].y + parts[i].h, h);
      for (int j = i + 1; j < 4; ++j) EXPECT_FALSE(overlap(parts[i], parts[j])) << i << " " << j;
    }
    EXPECT_FLOAT_EQ(sum, w * h);
  }
}

TEST(PanelLayout, KeepsTheRightColumnReadable) {
  EXPECT_FLOAT_EQ(panel_layout(1280.0f, 720.0f).search.w, 460.8f);  // 36 %
  EXPECT_FLOAT_EQ(panel_layout(3000.0f, 720.0f).search.w, 520.0f);  // at most 520
  EXPECT_FLOAT_EQ(panel_layout(640.0f, 400.0f).search.w, 320.0f);   // never more than half
  EXPECT_FLOAT_EQ(panel_layout(1280.0f, 720.0f).bar.h, 64.0f);
}

}  // namespace
}  // namespace stanceplan::gui
