#pragma once
// Anti-aliased text drawn on an Image with stb_truetype (libstb-dev) and a TrueType font from
// Debian's fonts-dejavu-core. Glyphs are rasterised at the exact pixel size with sub-pixel
// horizontal placement, so small captions stay crisp. Const methods are thread-safe.
#include <memory>
#include <string>
#include <string_view>

#include "render/image/color.h"
#include "render/image/image.h"

namespace stanceplan::render {

class Font {
 public:
  // Throws std::runtime_error naming the file when it is missing or not a TrueType font.
  explicit Font(const std::string& path);
  ~Font();
  Font(const Font&) = delete;
  Font& operator=(const Font&) = delete;

  // Horizontal advance of the UTF-8 text at `px` pixels (the font's em height).
  float width(std::string_view utf8, float px) const;
  float ascent(float px) const;   // above the baseline, positive
  float descent(float px) const;  // below the baseline, positive
  // Draws with the baseline starting at (x, baseline_y); returns the pen position after the text.
  float draw(Image& image, float x, float baseline_y, std::string_view utf8, float px,
             Color color) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

enum class FontWeight { Regular, Bold };

// DejaVu Sans from fonts-dejavu-core (or the file named by STANCEPLAN_FONT / STANCEPLAN_FONT_BOLD),
// loaded once; nullptr when no font file exists (callers then draw no text).
const Font* default_font(FontWeight weight = FontWeight::Regular);

// The text, shortened with an ellipsis when it is wider than max_width pixels at px.
std::string fit_text(const Font& font, const std::string& utf8, float px, float max_width);

// Decodes UTF-8 into code points (invalid bytes become U+FFFD).
std::u32string decode_utf8(std::string_view utf8);

}  // namespace stanceplan::render
