#pragma once
// Colours as sRGB components in [0, 1], with alpha; used by styles, overlays and text.
#include <cstdint>

namespace stanceplan::render {

struct Color {
  float r = 0.0f;
  float g = 0.0f;
  float b = 0.0f;
  float a = 1.0f;

  bool operator==(const Color&) const = default;
};

// 0xRRGGBB with an optional alpha.
constexpr Color rgb_hex(std::uint32_t hex, float alpha = 1.0f) {
  return Color{static_cast<float>((hex >> 16) & 0xff) / 255.0f,
               static_cast<float>((hex >> 8) & 0xff) / 255.0f,
               static_cast<float>(hex & 0xff) / 255.0f, alpha};
}

constexpr Color with_alpha(Color c, float alpha) {
  return Color{c.r, c.g, c.b, alpha};
}

}  // namespace stanceplan::render
