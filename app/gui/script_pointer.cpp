#include "app/gui/script_pointer.h"

#include <cmath>

namespace stanceplan::gui {
namespace {

constexpr int kDragFrames = 8;  // a drag is spread over frames, as a hand's would be

// Hover, press, move in kDragFrames steps, release.
std::deque<ScriptedPointer> drag(float x, float y, float dx, float dy) {
  std::deque<ScriptedPointer> moves;
  moves.push_back({x, y, false, false, 0.0f});
  moves.push_back({x, y, true, false, 0.0f});
  for (int i = 1; i <= kDragFrames; ++i) {
    const float t = static_cast<float>(i) / kDragFrames;
    moves.push_back({x + t * dx, y + t * dy, true, false, 0.0f});
  }
  moves.push_back({x + dx, y + dy, false, false, 0.0f});
  return moves;
}

// Hover (two frames: the hovered item of the frame before matters to overlapping items), press,
// release: ImGui's buttons fire on the release over them.
std::deque<ScriptedPointer> click(float x, float y) {
  return {{x, y, false, false, 0.0f},
          {x, y, false, false, 0.0f},
          {x, y, true, false, 0.0f},
          {x, y, false, false, 0.0f},
          {x, y, false, false, 0.0f}};
}

}  // namespace

std::deque<ScriptedPointer> scripted_pointer_moves(const ScriptAction& action, const Rect& view,
                                                   const Rect& reset_button) {
  const float cx = view.x + 0.5f * view.w, cy = view.y + 0.5f * view.h;
  switch (action.verb) {
    case ScriptVerb::Orbit:
      return drag(cx, cy, static_cast<float>(action.a), static_cast<float>(action.b));
    case ScriptVerb::Zoom:
      return {{cx, cy, false, false, 0.0f},
              {cx, cy, false, false, static_cast<float>(action.a)},
              {cx, cy, false, false, 0.0f}};
    case ScriptVerb::ResetView:
      return click(reset_button.x + 0.5f * reset_button.w, reset_button.y + 0.5f * reset_button.h);
    default:
      return {};
  }
}

}  // namespace stanceplan::gui
