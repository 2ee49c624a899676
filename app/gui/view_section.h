#pragma once
// The 3-D view: the renderer's latest image of what the panel shows, with mouse control of the
// camera (left drag: orbit; right or middle drag: pan; wheel: zoom) and a button to reframe.
#include "app/gui/orbit_camera.h"
#include "app/gui/panel_layout.h"
#include "app/gui/panel_state.h"
#include "app/gui/view_texture.h"

namespace stanceplan::gui {

// Returns true when the camera moved this frame.
bool draw_view_section(const Rect& area, const ViewTexture& texture, OrbitCamera& camera,
                       PanelState& state);

}  // namespace stanceplan::gui
