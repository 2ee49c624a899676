#pragma once
// The panel's own colours as plain values (no ImGui): ui_style.cpp applies them, and the window
// test looks for them in screenshots.
#include "render/image/color.h"

namespace stanceplan::gui {

// Window background of every panel section (opaque: the light 3-D view never shows through).
inline constexpr render::Color kPanelBackground = render::rgb_hex(0x1e2227);
// Behind everything else.
inline constexpr render::Color kWindowClear = render::rgb_hex(0x121417);
// Buttons at rest (opaque, so that they have one exact colour).
inline constexpr render::Color kButton = render::rgb_hex(0x2c4a6e);

}  // namespace stanceplan::gui
