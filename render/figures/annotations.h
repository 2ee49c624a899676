#pragma once
// Text drawn on rendered images: the caption (step, action, stance) and the colour legend. Both
// sit on translucent rounded panels so they stay readable over any background.
#include <string>

#include "render/image/image.h"
#include "render/render_style.h"

namespace stanceplan::render {

// Text size in pixels for an image of this height (scaled by the style's text_scale).
float text_px(int image_height, double text_scale = 1.0);

// The caption's lines ('\n'-separated) at the top-left corner; the first line in bold.
// Returns the panel's bottom edge in pixels (0 when nothing was drawn, e.g. no font installed).
int draw_caption(Image& image, const std::string& caption, float px);

// One entry per enabled overlay of `style` (loaded / unloaded contact, force, support polygon,
// centre of mass, friction cone), in rows at the bottom-left corner (or at (x, y) when given).
void draw_legend(Image& image, const RenderStyle& style, float px, int x = -1, int y = -1);
// Height in pixels the legend needs at this size and width (for layouts reserving space).
int legend_height(const RenderStyle& style, float px, int max_width);

}  // namespace stanceplan::render
