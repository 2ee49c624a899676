#pragma once
// The mean colour of a texture image (PNG, JPEG, BMP, TGA, ... through stb_image): what a
// texture-mapped mesh is drawn in. The renderer has no texture mapping: a mesh's visuals are one
// colour per material, and a texture's mean keeps a painted part its overall hue
// (docs/RENDERING.md).
#include <array>
#include <string>

namespace stanceplan::render {

// The mean sRGB colour (components in [0, 1]) of the image file's pixels, each weighted by its
// alpha (a fully transparent texture gives the plain mean). Throws std::runtime_error
// "texture \"PATH\" could not be read: REASON" when the file is missing or not an image.
std::array<float, 3> mean_texture_color(const std::string& path);

}  // namespace stanceplan::render
