#include "app/gui/panel_layout.h"

#include <algorithm>

namespace stanceplan::gui {

PanelLayout panel_layout(float width, float height) {
  const float column = std::min(std::clamp(0.36f * width, 340.0f, 520.0f), 0.5f * width);
  const float bar = std::min(64.0f, 0.25f * height);
  const float left = width - column;
  const float search = 0.55f * height;  // the tree gets the larger share of the column
  PanelLayout layout;
  layout.view = {0.0f, 0.0f, left, height - bar};
  layout.bar = {0.0f, height - bar, left, bar};
  layout.search = {left, 0.0f, column, search};
  layout.inspector = {left, search, column, height - search};
  return layout;
}

}  // namespace stanceplan::gui
