#pragma once
// Reduces true-colour frames to one palette of at most 256 colours, and maps pixels to palette
// indices. Frames with at most 256 distinct colours keep them exactly; otherwise median cut on a
// 5-bit-per-channel histogram, mapped through a 32768-entry lookup table.
#include <array>
#include <cstdint>
#include <unordered_map>
#include <vector>

#include "render/image/image.h"

namespace stanceplan::render {

class ColorQuantizer {
 public:
  // Builds the palette from every pixel of every frame.
  explicit ColorQuantizer(const std::vector<Image>& frames, int max_colors = 256);

  const std::vector<std::array<std::uint8_t, 3>>& palette() const { return palette_; }
  std::uint8_t index(const std::uint8_t* rgb) const;
  std::vector<std::uint8_t> map(const Image& frame) const;

 private:
  static int key(const std::uint8_t* rgb) {
    return ((rgb[0] >> 3) << 10) | ((rgb[1] >> 3) << 5) | (rgb[2] >> 3);
  }

  // Exact palettes only: the 256 colours, and the index of each packed 0xRRGGBB colour.
  bool build_exact(const std::vector<Image>& frames, int max_colors);
  static std::uint32_t packed(const std::uint8_t* rgb) {
    return (rgb[0] << 16) | (rgb[1] << 8) | rgb[2];
  }

  std::vector<std::array<std::uint8_t, 3>> palette_;
  std::vector<std::uint8_t> lut_;                          // median cut
  std::unordered_map<std::uint32_t, std::uint8_t> exact_;  // exact palettes
};

}  // namespace stanceplan::render
