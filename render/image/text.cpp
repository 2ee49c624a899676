#include "render/image/text.h"

#include <stb_truetype.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <vector>

namespace stanceplan::render {

struct Font::Impl {
  std::vector<unsigned char> data;  // stbtt_fontinfo points into it
  stbtt_fontinfo info{};
  int ascent = 0, descent = 0, line_gap = 0;
};

Font::Font(const std::string& path) : impl_(std::make_unique<Impl>()) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("font file \"" + path + "\" cannot be read");
  impl_->data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  const int offset = stbtt_GetFontOffsetForIndex(impl_->data.data(), 0);
  if (impl_->data.empty() || offset < 0 ||
      !stbtt_InitFont(&impl_->info, impl_->data.data(), offset))
    throw std::runtime_error("font file \"" + path + "\" is not a TrueType font");
  stbtt_GetFontVMetrics(&impl_->info, &impl_->ascent, &impl_->descent, &impl_->line_gap);
}

Font::~Font() = default;

float Font::ascent(float px) const {
  return static_cast<float>(impl_->ascent) * stbtt_ScaleForMappingEmToPixels(&impl_->info, px);
}

float Font::descent(float px) const {
  return -static_cast<float>(impl_->descent) * stbtt_ScaleForMappingEmToPixels(&impl_->info, px);
}

float Font::width(std::string_view utf8, float px) const {
  const float scale = stbtt_ScaleForMappingEmToPixels(&impl_->info, px);
  const std::u32string text = decode_utf8(utf8);
  float pen = 0.0f;
  for (size_t i = 0; i < text.size(); ++i) {
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&impl_->info, static_cast<int>(text[i]), &advance, &bearing);
    pen += static_cast<float>(advance) * scale;
    if (i + 1 < text.size())
      pen += scale * static_cast<float>(stbtt_GetCodepointKernAdvance(
                         &impl_->info, static_cast<int>(text[i]), static_cast<int>(text[i + 1])));
  }
  return pen;
}

float Font::draw(Image& image, float x, float baseline_y, std::string_view utf8, float px,
                 Color color) const {
  const float scale = stbtt_ScaleForMappingEmToPixels(&impl_->info, px);
  const std::u32string text = decode_utf8(utf8);
  const int baseline = static_cast<int>(std::lround(baseline_y));
  float pen = x;
  std::vector<unsigned char> coverage;
  for (size_t i = 0; i < text.size(); ++i) {
    const int cp = static_cast<int>(text[i]);
    const float shift = pen - std::floor(pen);  // sub-pixel placement keeps spacing even
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointBitmapBoxSubpixel(&impl_->info, cp, scale, scale, shift, 0.0f, &x0, &y0, &x1,
                                        &y1);
    const int w = x1 - x0, h = y1 - y0;
    if (w > 0 && h > 0) {
      coverage.assign(static_cast<size_t>(w) * h, 0);
      stbtt_MakeCodepointBitmapSubpixel(&impl_->info, coverage.data(), w, h, w, scale, scale, shift,
                                        0.0f, cp);
      const int left = static_cast<int>(std::floor(pen)) + x0;
      for (int v = 0; v < h; ++v)
        for (int u = 0; u < w; ++u)
          if (coverage[v * w + u] != 0)
            blend_pixel(image, left + u, baseline + y0 + v, color, coverage[v * w + u] / 255.0f);
    }
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&impl_->info, cp, &advance, &bearing);
    pen += static_cast<float>(advance) * scale;
    if (i + 1 < text.size())
      pen += scale * static_cast<float>(stbtt_GetCodepointKernAdvance(
                         &impl_->info, cp, static_cast<int>(text[i + 1])));
  }
  return pen;
}

namespace {

std::unique_ptr<Font> load_first(const char* env, const std::vector<std::string>& candidates) {
  std::vector<std::string> paths;
  if (const char* override_path = std::getenv(env)) paths.emplace_back(override_path);
  paths.insert(paths.end(), candidates.begin(), candidates.end());
  for (const std::string& path : paths) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) continue;
    try {
      return std::make_unique<Font>(path);
    } catch (const std::exception&) {
      continue;  // try the next candidate
    }
  }
  return nullptr;
}

}  // namespace

const Font* default_font(FontWeight weight) {
  static const std::unique_ptr<Font> regular = load_first(
      "STANCEPLAN_FONT",
      {"/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf", "/usr/share/fonts/TTF/DejaVuSans.ttf"});
  static const std::unique_ptr<Font> bold =
      load_first("STANCEPLAN_FONT_BOLD", {"/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf",
                                          "/usr/share/fonts/TTF/DejaVuSans-Bold.ttf"});
  if (weight == FontWeight::Bold && bold) return bold.get();
  return regular.get();
}

std::string fit_text(const Font& font, const std::string& utf8, float px, float max_width) {
  if (font.width(utf8, px) <= max_width) return utf8;
  const std::string ellipsis = "\u2026";
  std::string text = utf8;
  while (!text.empty()) {
    // Drop the last code point: its continuation bytes (10xxxxxx), then its lead byte.
    while (!text.empty() && (static_cast<unsigned char>(text.back()) & 0xC0) == 0x80)
      text.pop_back();
    if (!text.empty()) text.pop_back();
    if (font.width(text + ellipsis, px) <= max_width) return text + ellipsis;
  }
  return ellipsis;
}

std::u32string decode_utf8(std::string_view s) {
  std::u32string out;
  for (size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    int length = c < 0x80           ? 1
                 : (c >> 5) == 0x6  ? 2
                 : (c >> 4) == 0xe  ? 3
                 : (c >> 3) == 0x1e ? 4
                                    : 0;
    if (length == 0 || i + length > s.size()) {
      out.push_back(U'\uFFFD');
      ++i;
      continue;
    }
    char32_t cp = length == 1 ? c : c & (0x7f >> length);
    bool valid = true;
    for (int k = 1; k < length; ++k) {
      const auto cc = static_cast<unsigned char>(s[i + k]);
      valid &= (cc >> 6) == 0x2;
      cp = (cp << 6) | (cc & 0x3f);
    }
    out.push_back(valid ? cp : U'\uFFFD');
    i += valid ? length : 1;
  }
  return out;
}

}  // namespace stanceplan::render
