#pragma once
// An 8-bit RGBA image in memory, rows top-down (row 0 is the top of the picture), 4 bytes per
// pixel, no padding. What the renderer returns and what the PNG and GIF writers consume.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "render/image/color.h"

namespace stanceplan::render {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;

  Image() = default;
  Image(int w, int h, Color fill = Color{1.0f, 1.0f, 1.0f, 1.0f});

  bool empty() const { return width == 0 || height == 0; }
  std::uint8_t* pixel(int x, int y) {
    return rgba.data() + (static_cast<size_t>(y) * width + x) * 4;
  }
  const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + (static_cast<size_t>(y) * width + x) * 4;
  }
  bool operator==(const Image&) const = default;
};

std::uint8_t to_byte(float v);

// Blends `color` (with its alpha times `coverage`) over the pixel; out-of-range pixels are ignored.
void blend_pixel(Image& image, int x, int y, Color color, float coverage = 1.0f);
// Blends a filled rectangle, clipped to the image.
void fill_rect(Image& image, int x, int y, int w, int h, Color color);
// Blends a filled rectangle with rounded corners of radius r (anti-aliased), clipped.
void fill_rounded_rect(Image& image, int x, int y, int w, int h, float r, Color color);
// Copies src into dst with src's top-left corner at (x, y), clipped.
void paste(Image& dst, const Image& src, int x, int y);
// Area-averaging resize (good for shrinking; used for thumbnails and GIF frames).
Image resize_area(const Image& src, int width, int height);

}  // namespace stanceplan::render
