#pragma once
// Anti-aliasing after rendering, on the CPU, for images rendered without multisampling: the
// edge-directed filter of FXAA (find the local edge, its orientation and how far its ends are,
// then blend each edge pixel with its neighbour across the edge by its position along the step
// of the staircase). On the CPU because most pixels are not on an edge and return early, while
// llvmpipe would run the whole filter for every pixel.
#include "render/image/image.h"

namespace stanceplan::render {

// In place; pixels away from edges keep their exact values. Alpha is left unchanged.
void smooth_edges(Image& image);

}  // namespace stanceplan::render
