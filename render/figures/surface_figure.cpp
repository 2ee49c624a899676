#include "render/figures/surface_figure.h"

#include <algorithm>
#include <cmath>

#include "render/figures/annotations.h"
#include "render/image/text.h"
#include "render/scene/surface_overlays.h"

namespace stanceplan::render {
namespace {

struct Rect {
  float x, y, w, h;
  bool overlaps(const Rect& o) const {
    return x < o.x + o.w && o.x < x + w && y < o.y + o.h && o.y < y + h;
  }
};

// A name on a white rounded panel at `rect`.
void draw_tag(Image& image, const Font& font, const Rect& rect, const std::string& text,
              Color color, float px) {
  const float pad = 0.3f * px;
  fill_rounded_rect(image, static_cast<int>(rect.x), static_cast<int>(rect.y),
                    static_cast<int>(rect.w), static_cast<int>(rect.h), 0.3f * rect.h,
                    rgb_hex(0xffffff, 0.85f));
  font.draw(image, rect.x + pad, rect.y + pad + font.ascent(px), text, px, color);
}

Rect tag_rect(const Font& font, const std::string& text, float px) {
  const float pad = 0.3f * px;
  return {0.0f, 0.0f, font.width(text, px) + 2.0f * pad,
          font.ascent(px) + font.descent(px) + 2.0f * pad};
}

// Each name centred on its surface, in SurfaceSet order; a name that would cover one already
// placed is left out there (the list at the right still names every surface).
void draw_labels(Image& image, const Camera& camera, const std::vector<SurfaceLabel>& labels,
                 float px) {
  const Font* font = default_font(FontWeight::Bold);
  if (font == nullptr) return;
  std::vector<Rect> placed;
  for (const SurfaceLabel& label : labels) {
    Eigen::Vector2d pixel;
    if (!project_to_pixel(camera, image.width, image.height, label.p_W, pixel)) continue;
    Rect r = tag_rect(*font, label.text, px);
    // A point's name starts beside it (its sphere is a few pixels wide); a polygon's is centred.
    r.x = static_cast<float>(pixel.x()) - (label.point ? -0.6f * r.h : 0.5f * r.w);
    r.y = static_cast<float>(pixel.y()) - 0.5f * r.h;
    if (r.x < 0 || r.y < 0 || r.x + r.w > image.width || r.y + r.h > image.height) continue;
    if (std::any_of(placed.begin(), placed.end(), [&](const Rect& p) { return p.overlaps(r); }))
      continue;
    placed.push_back(r);
    draw_tag(image, *font, r, label.text, label.color, px);
  }
}

// Every name, one per row, down the right edge; "... and N more" when they do not all fit.
void draw_name_list(Image& image, const std::vector<SurfaceLabel>& labels, float px) {
  const Font* font = default_font(FontWeight::Bold);
  if (font == nullptr || labels.empty()) return;
  const float row = 1.35f * px;
  const int rows = static_cast<int>((image.height - 2.0f * px) / row);
  const int shown = static_cast<int>(labels.size()) <= rows ? static_cast<int>(labels.size())
                                                            : std::max(0, rows - 1);
  float width = 0.0f;
  for (int i = 0; i < shown; ++i) width = std::max(width, font->width(labels[i].text, px));
  const float x = image.width - width - 1.5f * px;
  fill_rounded_rect(
      image, static_cast<int>(x - 0.5f * px), static_cast<int>(0.5f * px),
      static_cast<int>(width + px),
      static_cast<int>((shown + (shown < static_cast<int>(labels.size())) + 0.5f) * row), 0.4f * px,
      rgb_hex(0xffffff, 0.82f));
  float baseline = px + font->ascent(px);
  for (int i = 0; i < shown; ++i, baseline += row)
    font->draw(image, x, baseline, labels[i].text, px, labels[i].color);
  if (shown < static_cast<int>(labels.size()))
    font->draw(image, x, baseline, "... and " + std::to_string(labels.size() - shown) + " more", px,
               rgb_hex(0x1d232b));
}

}  // namespace

Image render_surface_figure(Renderer& renderer, const Scene& scene, const Eigen::VectorXd& q,
                            View view, const std::string& caption) {
  DrawList list = renderer.assemble(scene, q, {}, {});
  const SystemPose pose(scene.system, q);
  std::vector<SurfaceLabel> labels = add_surface_overlays(scene, pose, renderer.style(), list);
  if (scene.system.num_entities() == 1)  // one model: its surfaces' own names
    for (SurfaceLabel& label : labels) label.text = label.text.substr(label.text.find('/') + 1);
  Eigen::AlignedBox3d box = list.bounds();
  if (box.isEmpty()) box = list.bounds(true);
  const double aspect = static_cast<double>(renderer.width()) / renderer.height();
  const Camera camera = frame_box(box, view, aspect, frame_margins(renderer.style()));
  Image image = renderer.render(list, camera);
  const float px = text_px(renderer.height(), renderer.style().text_scale);
  draw_labels(image, camera, labels, 0.7f * px);
  draw_name_list(image, labels, 0.7f * px);
  if (!caption.empty()) draw_caption(image, caption, px);
  return image;
}

}  // namespace stanceplan::render
