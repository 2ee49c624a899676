#pragma once
// Where each part of the panel goes in a window of a given size: the 3-D view fills the left,
// the timeline / status bar runs under it, and the right column holds the search controls with
// the tree above the inspector of the selected node.
namespace stanceplan::gui {

struct Rect {
  float x = 0, y = 0, w = 0, h = 0;
};

struct PanelLayout {
  Rect view;       // the 3-D view
  Rect bar;        // timeline when a plan is found, search status before
  Rect search;     // controls and tree
  Rect inspector;  // the selected node
};

// The right column is 36 % of the width, kept between 340 and 520 pixels (and never more than
// half the window); the bar is 64 pixels high.
PanelLayout panel_layout(float width, float height);

}  // namespace stanceplan::gui
