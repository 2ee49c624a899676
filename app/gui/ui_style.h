#pragma once
// The panel's look: Dear ImGui's dark theme made opaque (the 3-D view beside it is light, so the
// two regions never blend), DejaVu Sans for legible text, and the colours the tree and the
// inspector give to node states and contact states (the same green / orange as the renderer's
// loaded / unloaded contacts).
#include <imgui.h>

#include "app/gui/panel_palette.h"
#include "app/gui/search_tree.h"

namespace stanceplan::gui {

inline constexpr float kFontPixels = 15.0f;

// Colours and rounding; loads DejaVu Sans (STANCEPLAN_FONT overrides) when it is installed, else
// keeps ImGui's built-in font. Call once, after ImGui::CreateContext.
void apply_ui_style();

ImVec4 to_imvec(render::Color c);
ImVec4 status_color(NodeStatus status);
ImVec4 loaded_color();    // contact carrying force
ImVec4 unloaded_color();  // touching, no force
ImVec4 rejected_color();  // candidate not accepted
ImVec4 muted_text_color();
// A section's title: muted text over a separator line.
void section_title(const char* title);

}  // namespace stanceplan::gui
