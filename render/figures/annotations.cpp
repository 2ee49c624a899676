#include "render/figures/annotations.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "render/image/text.h"

namespace stanceplan::render {
namespace {

const Color kText = rgb_hex(0x1d232b);
const Color kPanel = rgb_hex(0xffffff, 0.82f);

enum class Swatch { Square, Arrow, Disc, Outline };

struct Entry {
  Swatch swatch;
  Color color;
  std::string label;
};

std::vector<Entry> legend_entries(const RenderStyle& style) {
  std::vector<Entry> entries;
  if (style.contacts) {
    entries.push_back({Swatch::Square, style.loaded_contact, "loaded contact"});
    entries.push_back({Swatch::Square, style.unloaded_contact, "touching, no force"});
  }
  if (style.forces) entries.push_back({Swatch::Arrow, style.force_color, "contact force"});
  if (style.friction_cones)
    entries.push_back({Swatch::Square, with_alpha(style.cone_color, 0.6f), "friction cone"});
  if (style.support_polygon)
    entries.push_back({Swatch::Outline, style.support_color, "support polygon"});
  if (style.center_of_mass) entries.push_back({Swatch::Disc, style.com_color, "centre of mass"});
  return entries;
}

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

void draw_swatch(Image& image, const Entry& e, int x, int y, int size) {
  switch (e.swatch) {
    case Swatch::Square:
      fill_rounded_rect(image, x, y, size, size, 0.2f * size, e.color);
      break;
    case Swatch::Disc:
      fill_rounded_rect(image, x + size / 6, y + size / 6, size - size / 3, size - size / 3, size,
                        e.color);
      break;
    case Swatch::Outline:
      fill_rounded_rect(image, x, y, size, size, 0.2f * size, with_alpha(e.color, 0.35f));
      fill_rounded_rect(image, x, y, size, std::max(2, size / 7), 0.0f, with_alpha(e.color, 1.0f));
      break;
    case Swatch::Arrow: {
      // A shaft and a head drawn pixel by pixel: the head is a triangle pointing right.
      const int thickness = std::max(2, size / 6);
      const int head = size / 2;
      fill_rect(image, x, y + size / 2 - thickness / 2, size - head + 1, thickness, e.color);
      for (int u = 0; u < head; ++u) {
        const float half = 0.5f * size * (1.0f - static_cast<float>(u) / head) * 0.8f;
        for (int v = static_cast<int>(-std::ceil(half)); v <= static_cast<int>(std::ceil(half));
             ++v) {
          const float coverage =
              std::clamp(half - std::abs(static_cast<float>(v)) + 0.5f, 0.0f, 1.0f);
          blend_pixel(image, x + size - head + u, y + size / 2 + v, e.color, coverage);
        }
      }
      break;
    }
  }
}

// Lays entries out in rows no wider than max_width; returns each entry's (x, row).
std::vector<std::pair<int, int>> layout(const std::vector<Entry>& entries, const Font& font,
                                        float px, int max_width, int* rows, int* width) {
  const int swatch = static_cast<int>(std::lround(px)),
            gap = static_cast<int>(std::lround(0.45f * px));
  const int spacing = static_cast<int>(std::lround(1.3f * px));
  std::vector<std::pair<int, int>> at;
  int x = 0, row = 0;
  *width = 0;
  for (const Entry& e : entries) {
    const int w = swatch + gap + static_cast<int>(std::ceil(font.width(e.label, px)));
    if (x > 0 && x + w > max_width) {
      x = 0;
      ++row;
    }
    at.emplace_back(x, row);
    x += w + spacing;
    *width = std::max(*width, x - spacing);
  }
  *rows = row + 1;
  return at;
}

}  // namespace

float text_px(int image_height, double text_scale) {
  return static_cast<float>(std::max(11.0, std::round(image_height * 0.028 * text_scale)));
}

int draw_caption(Image& image, const std::string& caption, float px) {
  const Font* bold = default_font(FontWeight::Bold);
  const Font* regular = default_font(FontWeight::Regular);
  const std::vector<std::string> lines = split_lines(caption);
  if (bold == nullptr || regular == nullptr || lines.empty()) return 0;
  const float first_px = std::round(px * 1.15f);
  const int pad = static_cast<int>(std::lround(0.7f * px)),
            margin = static_cast<int>(std::lround(0.8f * px));
  const float line_height = std::round(1.45f * px);
  const int max_width = image.width - 2 * margin - 2 * pad;
  std::vector<std::string> fitted;
  float width = 0.0f;
  for (size_t i = 0; i < lines.size(); ++i) {
    const Font* font = i == 0 ? bold : regular;
    const float size = i == 0 ? first_px : px;
    fitted.push_back(fit_text(*font, lines[i], size, static_cast<float>(max_width)));
    width = std::max(width, font->width(fitted.back(), size));
  }
  const int panel_w =
      static_cast<int>(std::ceil(std::min<float>(width, static_cast<float>(max_width)))) + 2 * pad;
  const int panel_h =
      static_cast<int>(std::round(first_px * 1.45f + line_height * (lines.size() - 1))) + 2 * pad -
      static_cast<int>(std::round(0.35f * px));
  fill_rounded_rect(image, margin, margin, panel_w, panel_h, 0.5f * px, kPanel);
  float baseline = static_cast<float>(margin + pad) + bold->ascent(first_px);
  for (size_t i = 0; i < lines.size(); ++i) {
    const Font* font = i == 0 ? bold : regular;
    font->draw(image, static_cast<float>(margin + pad), baseline, fitted[i], i == 0 ? first_px : px,
               i == 0 ? kText : with_alpha(kText, 0.85f));
    baseline += i == 0 ? std::round(first_px * 1.45f) : line_height;
  }
  return margin + panel_h;
}

int legend_height(const RenderStyle& style, float px, int max_width) {
  const Font* font = default_font();
  const std::vector<Entry> entries = legend_entries(style);
  if (font == nullptr || entries.empty()) return 0;
  int rows = 0, width = 0;
  layout(entries, *font, px, max_width, &rows, &width);
  const int pad = static_cast<int>(std::lround(0.6f * px));
  return rows * static_cast<int>(std::lround(1.5f * px)) + 2 * pad;
}

void draw_legend(Image& image, const RenderStyle& style, float px, int x, int y) {
  const Font* font = default_font();
  const std::vector<Entry> entries = legend_entries(style);
  if (font == nullptr || entries.empty()) return;
  const int pad = static_cast<int>(std::lround(0.6f * px)),
            margin = static_cast<int>(std::lround(0.8f * px));
  const int row_height = static_cast<int>(std::lround(1.5f * px));
  int rows = 0, width = 0;
  const auto at = layout(entries, *font, px, image.width - 2 * margin - 2 * pad, &rows, &width);
  const int panel_w = width + 2 * pad, panel_h = rows * row_height + 2 * pad;
  if (x < 0) x = margin;
  if (y < 0) y = image.height - margin - panel_h;
  fill_rounded_rect(image, x, y, panel_w, panel_h, 0.5f * px, kPanel);
  const int swatch = static_cast<int>(std::lround(px)),
            gap = static_cast<int>(std::lround(0.45f * px));
  for (size_t i = 0; i < entries.size(); ++i) {
    const int ex = x + pad + at[i].first, ey = y + pad + at[i].second * row_height;
    const int sy = ey + (row_height - swatch) / 2;
    draw_swatch(image, entries[i], ex, sy, swatch);
    const float baseline =
        static_cast<float>(ey) + 0.5f * row_height + 0.5f * (font->ascent(px) - font->descent(px));
    font->draw(image, static_cast<float>(ex + swatch + gap), std::round(baseline), entries[i].label,
               px, kText);
  }
}

}  // namespace stanceplan::render
