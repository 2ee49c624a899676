#include "render/image/image.h"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace stanceplan::render {

Image::Image(int w, int h, Color fill) : width(w), height(h) {
  rgba.resize(static_cast<size_t>(w) * h * 4);
  const std::uint8_t px[4] = {to_byte(fill.r), to_byte(fill.g), to_byte(fill.b), to_byte(fill.a)};
  for (size_t i = 0; i < rgba.size(); i += 4) std::memcpy(&rgba[i], px, 4);
}

std::uint8_t to_byte(float v) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
}

void blend_pixel(Image& image, int x, int y, Color color, float coverage) {
  if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
  const float alpha = std::clamp(color.a * coverage, 0.0f, 1.0f);
  if (alpha <= 0.0f) return;
  std::uint8_t* p = image.pixel(x, y);
  const float src[3] = {color.r, color.g, color.b};
  for (int c = 0; c < 3; ++c) {
    const float dst = static_cast<float>(p[c]) / 255.0f;
    p[c] = to_byte(src[c] * alpha + dst * (1.0f - alpha));
  }
  const float dst_a = static_cast<float>(p[3]) / 255.0f;
  p[3] = to_byte(alpha + dst_a * (1.0f - alpha));
}

void fill_rect(Image& image, int x, int y, int w, int h, Color color) {
  const int x0 = std::max(x, 0), y0 = std::max(y, 0);
  const int x1 = std::min(x + w, image.width), y1 = std::min(y + h, image.height);
  for (int yy = y0; yy < y1; ++yy)
    for (int xx = x0; xx < x1; ++xx) blend_pixel(image, xx, yy, color);
}

void fill_rounded_rect(Image& image, int x, int y, int w, int h, float r, Color color) {
  r = std::min({r, 0.5f * static_cast<float>(w), 0.5f * static_cast<float>(h)});
  const int x0 = std::max(x, 0), y0 = std::max(y, 0);
  const int x1 = std::min(x + w, image.width), y1 = std::min(y + h, image.height);
  for (int yy = y0; yy < y1; ++yy) {
    for (int xx = x0; xx < x1; ++xx) {
      // Signed distance of the pixel centre to the rounded rectangle, as coverage (1 px ramp).
      const float px = static_cast<float>(xx) + 0.5f, py = static_cast<float>(yy) + 0.5f;
      const float cx = std::clamp(px, x + r, x + w - r), cy = std::clamp(py, y + r, y + h - r);
      const float d = std::hypot(px - cx, py - cy) - r;
      blend_pixel(image, xx, yy, color, std::clamp(0.5f - d, 0.0f, 1.0f));
    }
  }
}

void paste(Image& dst, const Image& src, int x, int y) {
  const int x0 = std::max(x, 0), x1 = std::min(x + src.width, dst.width);
  if (x1 <= x0) return;
  for (int yy = std::max(y, 0); yy < std::min(y + src.height, dst.height); ++yy) {
    std::memcpy(dst.pixel(x0, yy), src.pixel(x0 - x, yy - y), static_cast<size_t>(x1 - x0) * 4);
  }
}

Image resize_area(const Image& src, int width, int height) {
  Image out(width, height);
  const double sx = static_cast<double>(src.width) / width;
  const double sy = static_cast<double>(src.height) / height;
  for (int y = 0; y < height; ++y) {
    const double fy0 = y * sy, fy1 = (y + 1) * sy;
    for (int x = 0; x < width; ++x) {
      const double fx0 = x * sx, fx1 = (x + 1) * sx;
      double acc[4] = {0, 0, 0, 0};
      double total = 0.0;
      // Every source pixel overlapping the destination pixel, weighted by the overlap area.
      for (int v = static_cast<int>(fy0);
           v < std::min(static_cast<int>(std::ceil(fy1)), src.height); ++v) {
        const double wy = std::min<double>(v + 1, fy1) - std::max<double>(v, fy0);
        for (int u = static_cast<int>(fx0);
             u < std::min(static_cast<int>(std::ceil(fx1)), src.width); ++u) {
          const double w = wy * (std::min<double>(u + 1, fx1) - std::max<double>(u, fx0));
          const std::uint8_t* p = src.pixel(u, v);
          for (int c = 0; c < 4; ++c) acc[c] += w * p[c];
          total += w;
        }
      }
      std::uint8_t* q = out.pixel(x, y);
      for (int c = 0; c < 4; ++c) q[c] = static_cast<std::uint8_t>(std::lround(acc[c] / total));
    }
  }
  return out;
}

}  // namespace stanceplan::render
