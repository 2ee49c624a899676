#pragma once
// The mouse moves of a scripted action, one pointer state per frame, as a user would make them:
// `orbit DX DY` a left drag from the middle of the 3-D view, `zoom N` wheel clicks over it,
// `reset view` a hover, press and release on the view's Reset view button. The panel plays them
// through GuiWindow::begin_frame, so ImGui's own hover and click rules decide what they do.
#include <deque>

#include "app/gui/gui_window.h"
#include "app/gui/panel_layout.h"
#include "app/gui/panel_script.h"

namespace stanceplan::gui {

// Empty for verbs that are not mouse moves. `reset_button`: where the button was last drawn.
std::deque<ScriptedPointer> scripted_pointer_moves(const ScriptAction& action, const Rect& view,
                                                   const Rect& reset_button);

}  // namespace stanceplan::gui
