#include "render/image/edge_smoothing.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace stanceplan::render {
namespace {

constexpr int kMaxSearch = 8;  // pixels walked along an edge on each side
// Contrast below this is no edge worth smoothing: shading gradients, and the ground grid, which
// the shader already draws anti-aliased. Same values as the integer test in smooth_edges.
constexpr float kThresholdMin = 12.0f / 255.0f;
constexpr float kThresholdRel = 1.0f / 6.0f;

// Luminance in 8 bits: enough to find edges, and a quarter of the memory traffic of floats.
struct LumaPlane {
  int width;
  int height;
  std::vector<std::uint8_t> luma;
  float at(int x, int y) const {
    x = std::clamp(x, 0, width - 1);
    y = std::clamp(y, 0, height - 1);
    return static_cast<float>(luma[static_cast<size_t>(y) * width + x]) * (1.0f / 255.0f);
  }
};

LumaPlane luma_of(const Image& image) {
  LumaPlane plane{image.width, image.height,
                  std::vector<std::uint8_t>(static_cast<size_t>(image.width) * image.height)};
  for (size_t i = 0; i < plane.luma.size(); ++i) {
    const std::uint8_t* p = &image.rgba[4 * i];
    plane.luma[i] = static_cast<std::uint8_t>((77 * p[0] + 150 * p[1] + 29 * p[2] + 128) >> 8);
  }
  return plane;
}

// How far (0..1) the pixel should move towards its neighbour across the edge, whose offset goes
// to (*dx, *dy); 0 when the pixel is not on an edge.
float blend_amount(const LumaPlane& L, int x, int y, int* dx, int* dy) {
  const float c = L.at(x, y), n = L.at(x, y - 1), s = L.at(x, y + 1), w = L.at(x - 1, y),
              e = L.at(x + 1, y);
  const float lo = std::min({c, n, s, w, e}), hi = std::max({c, n, s, w, e});
  const float range = hi - lo;
  if (range < std::max(kThresholdMin, hi * kThresholdRel)) return 0.0f;
  const float nw = L.at(x - 1, y - 1), ne = L.at(x + 1, y - 1), sw = L.at(x - 1, y + 1),
              se = L.at(x + 1, y + 1);
  // Orientation: a horizontal edge changes most from row to row (second differences in y).
  const float change_in_y = std::abs(nw + sw - 2.0f * w) + 2.0f * std::abs(n + s - 2.0f * c) +
                            std::abs(ne + se - 2.0f * e);
  const float change_in_x = std::abs(nw + ne - 2.0f * n) + 2.0f * std::abs(w + e - 2.0f * c) +
                            std::abs(sw + se - 2.0f * s);
  const bool horizontal = change_in_y >= change_in_x;
  // The side of the edge with the steeper step.
  const float l1 = horizontal ? n : w, l2 = horizontal ? s : e;
  const bool side1 = std::abs(l1 - c) >= std::abs(l2 - c);
  const float side_luma = side1 ? l1 : l2;
  const float gradient = 0.25f * std::max(std::abs(l1 - c), std::abs(l2 - c));
  const float local_average = 0.5f * (side_luma + c);
  *dx = horizontal ? 0 : (side1 ? -1 : 1);
  *dy = horizontal ? (side1 ? -1 : 1) : 0;

  // Walk along the edge (between this row and the side's) until its contrast changes: the ends.
  const int ax = horizontal ? 1 : 0, ay = horizontal ? 0 : 1;
  float end_luma[2] = {0.0f, 0.0f};
  int distance[2] = {kMaxSearch, kMaxSearch};
  for (int k = 0; k < 2; ++k) {
    const int sign = k == 0 ? -1 : 1;
    for (int i = 1; i <= kMaxSearch; ++i) {
      const int px = x + sign * i * ax, py = y + sign * i * ay;
      const float here = 0.5f * (L.at(px, py) + L.at(px + *dx, py + *dy)) - local_average;
      if (std::abs(here) >= gradient) {
        end_luma[k] = here;
        distance[k] = i;
        break;
      }
      end_luma[k] = here;
    }
  }
  const bool closer_negative = distance[0] < distance[1];
  const float nearest = static_cast<float>(std::min(distance[0], distance[1]));
  const float edge_offset = 0.5f - nearest / static_cast<float>(distance[0] + distance[1]);
  // Blend only when the nearest end varies the way the pixel does (it is on the step's lower side).
  const bool centre_smaller = c < local_average;
  const bool coherent = ((closer_negative ? end_luma[0] : end_luma[1]) < 0.0f) != centre_smaller;
  float amount = coherent ? edge_offset : 0.0f;

  // Sub-pixel features (thin lines, single pixels) also blend, by their contrast to the 3x3 mean.
  const float mean = (2.0f * (n + s + w + e) + nw + ne + sw + se) / 12.0f;
  const float sub = std::clamp(std::abs(mean - c) / range, 0.0f, 1.0f);
  const float smooth = (-2.0f * sub + 3.0f) * sub * sub;
  amount = std::max(amount, 0.75f * smooth * smooth);
  return amount;
}

}  // namespace

void smooth_edges(Image& image) {
  if (image.width < 3 || image.height < 3) return;
  const LumaPlane luma = luma_of(image);
  // A cheap integer test first: almost every pixel is not on an edge and stops there.
  std::vector<std::uint8_t> l8(luma.luma.size());
  for (size_t i = 0; i < l8.size(); ++i)
    l8[i] = static_cast<std::uint8_t>(luma.luma[i] * 255.0f + 0.5f);
  const int w = image.width;
  struct Blend {
    size_t index;
    std::uint8_t rgb[3];
  };
  std::vector<Blend> blends;  // applied after the pass: every blend reads unfiltered neighbours
  for (int y = 0; y < image.height; ++y) {
    const bool border_row = y == 0 || y == image.height - 1;
    for (int x = 0; x < w; ++x) {
      const size_t i = static_cast<size_t>(y) * w + x;
      // A cheap integer test first: almost every pixel is not on an edge and stops here.
      if (!border_row && x > 0 && x < w - 1) {
        const int c = l8[i], n = l8[i - w], s = l8[i + w], west = l8[i - 1], e = l8[i + 1];
        const int hi = std::max({c, n, s, west, e}), lo = std::min({c, n, s, west, e});
        if (hi - lo < std::max(12, hi / 6)) continue;
      }
      int dx = 0, dy = 0;
      const float amount = blend_amount(luma, x, y, &dx, &dy);
      if (amount <= 0.0f) continue;
      const int nx = std::clamp(x + dx, 0, w - 1), ny = std::clamp(y + dy, 0, image.height - 1);
      const std::uint8_t* a = image.pixel(x, y);
      const std::uint8_t* b = image.pixel(nx, ny);
      Blend blend{i, {0, 0, 0}};
      for (int k = 0; k < 3; ++k)
        blend.rgb[k] = static_cast<std::uint8_t>(
            std::lround(a[k] + amount * (static_cast<float>(b[k]) - a[k])));
      blends.push_back(blend);
    }
  }
  for (const Blend& blend : blends) std::copy_n(blend.rgb, 3, &image.rgba[4 * blend.index]);
}

}  // namespace stanceplan::render
