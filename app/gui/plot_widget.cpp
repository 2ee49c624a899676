#include "app/gui/plot_widget.h"

#include <algorithm>
#include <cstdio>
#include <limits>

#include "app/gui/plot_ticks.h"
#include "app/gui/ui_style.h"

namespace stanceplan::gui {
namespace {

constexpr float kInset = 6.0f;          // px between the frame and the outermost data
constexpr float kPickRadius = 14.0f;    // px: farther points are not "under the pointer"
constexpr float kTickGap = 4.0f;        // px between a tick label and the frame
constexpr float kMinTickSpace = 26.0f;  // px of height per y tick label, at least
constexpr float kLegendGap = 12.0f;     // px between legend items on a line

// Data coordinates to screen pixels over the plotted area.
struct PlotFrame {
  ImVec2 min, max;  // the plotted area (the frame, without the tick labels)
  double x0 = 0.0, x1 = 1.0, y0 = 0.0, y1 = 1.0;

  ImVec2 to_screen(double x, double y) const {
    const float fx = float((x - x0) / (x1 - x0)), fy = float((y - y0) / (y1 - y0));
    return ImVec2(min.x + kInset + fx * (max.x - min.x - 2 * kInset),
                  max.y - kInset - fy * (max.y - min.y - 2 * kInset));
  }
};

// The range of every point, widened so that a single value or a flat series still has an axis;
// y starts at 0 for non-negative data (times, ratios, forces read against zero).
void fit_range(PlotFrame& f, const std::vector<PlotTrace>& traces, const PlotOptions& options) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  double x0 = kInf, x1 = -kInf, y0 = 0.0, y1 = options.y_at_least;
  for (const PlotTrace& t : traces)
    for (const PlotPoint& p : t.series->points) {
      x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
      y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
    }
  if (x0 > x1) x0 = 0.0, x1 = 1.0;
  if (std::isfinite(options.marker_x)) x0 = std::min(x0, options.marker_x);
  if (std::isfinite(options.marker_x)) x1 = std::max(x1, options.marker_x);
  if (x1 - x0 < 1e-9) x0 -= 1.0, x1 += 1.0;
  if (std::isfinite(options.limit_y)) y1 = std::max(y1, options.limit_y);
  if (y1 - y0 < 1e-9) y1 = y0 + 1.0;
  f.x0 = x0, f.x1 = x1, f.y0 = y0, f.y1 = y1 + 0.04 * (y1 - y0);  // headroom over the top point
}

ImU32 muted(float alpha) {
  ImVec4 c = muted_text_color();
  c.w = alpha;
  return ImGui::ColorConvertFloat4ToU32(c);
}

float widest_label(const AxisTicks& ticks) {
  float w = 0.0f;
  for (double v : ticks.values)
    w = std::max(w, ImGui::CalcTextSize(tick_label(v, ticks.step).c_str()).x);
  return w;
}

// Grid lines and labels at round values; x labels centred under their tick, kept inside.
void draw_axes(ImDrawList* dl, const PlotFrame& f, const AxisTicks& xt, const AxisTicks& yt) {
  dl->AddRectFilled(f.min, f.max, ImGui::GetColorU32(ImGuiCol_FrameBg));
  const float line = ImGui::GetTextLineHeight();
  for (double v : yt.values) {
    const float y = f.to_screen(f.x0, v).y;
    dl->AddLine(ImVec2(f.min.x, y), ImVec2(f.max.x, y), muted(0.18f));
    const std::string label = tick_label(v, yt.step);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    dl->AddText(ImVec2(f.min.x - kTickGap - w, y - 0.5f * line), muted(1.0f), label.c_str());
  }
  for (double v : xt.values) {
    const float x = f.to_screen(v, f.y0).x;
    dl->AddLine(ImVec2(x, f.max.y), ImVec2(x, f.max.y + 3.0f), muted(0.8f));
    const std::string label = tick_label(v, xt.step);
    const float w = ImGui::CalcTextSize(label.c_str()).x;
    const float left = std::clamp(x - 0.5f * w, f.min.x - kTickGap, f.max.x - w);
    dl->AddText(ImVec2(left, f.max.y + 3.0f), muted(1.0f), label.c_str());
  }
  dl->AddRect(f.min, f.max, muted(0.45f));
}

void draw_trace(ImDrawList* dl, const PlotFrame& f, const PlotTrace& t) {
  const ImU32 color = ImGui::ColorConvertFloat4ToU32(t.color);
  const std::vector<PlotPoint>& points = t.series->points;
  if (t.style != TraceStyle::Points && points.size() >= 2) {
    std::vector<ImVec2> line;
    for (size_t i = 0; i < points.size(); ++i) {
      const ImVec2 p = f.to_screen(points[i].x, points[i].y);
      // A staircase holds each value until the next point.
      if (t.style == TraceStyle::Stairs && i > 0) line.emplace_back(p.x, line.back().y);
      line.push_back(p);
    }
    dl->AddPolyline(line.data(), int(line.size()), color, ImDrawFlags_None, 1.6f);
  }
  if (t.style == TraceStyle::Lines) return;
  // Thousands of candidates share a few hundred pixels: smaller dots keep them apart.
  const float radius = points.size() > 1500 ? 1.8f : points.size() > 300 ? 2.4f : 3.2f;
  for (const PlotPoint& p : points)
    dl->AddCircleFilled(f.to_screen(p.x, p.y), radius, color, radius > 2.5f ? 12 : 6);
}

void draw_guides(ImDrawList* dl, const PlotFrame& f, const PlotOptions& options) {
  if (std::isfinite(options.limit_y)) {
    const float y = f.to_screen(f.x0, options.limit_y).y;
    for (float x = f.min.x; x < f.max.x; x += 8.0f)  // dashed: a bound, not data
      dl->AddLine(ImVec2(x, y), ImVec2(std::min(x + 4.0f, f.max.x), y),
                  ImGui::ColorConvertFloat4ToU32(rejected_color()), 1.2f);
  }
  if (std::isfinite(options.marker_x)) {
    const float x = f.to_screen(options.marker_x, f.y0).x;
    dl->AddLine(ImVec2(x, f.min.y), ImVec2(x, f.max.y), IM_COL32(255, 255, 255, 170), 1.5f);
  }
}

// The pickable point nearest the pointer, within kPickRadius.
PlotPick nearest_point(const PlotFrame& f, const std::vector<PlotTrace>& traces, ImVec2 mouse) {
  PlotPick pick;
  float best = kPickRadius * kPickRadius;
  for (size_t t = 0; t < traces.size(); ++t) {
    if (!traces[t].pickable) continue;
    const std::vector<PlotPoint>& points = traces[t].series->points;
    for (size_t i = 0; i < points.size(); ++i) {
      const ImVec2 p = f.to_screen(points[i].x, points[i].y);
      const float d = (p.x - mouse.x) * (p.x - mouse.x) + (p.y - mouse.y) * (p.y - mouse.y);
      if (d <= best) best = d, pick.trace = int(t), pick.point = int(i);
    }
  }
  return pick;
}

std::string readable(double value, bool whole) {
  char text[32];
  const double a = std::abs(value);
  const int decimals = whole || a >= 100.0 ? 0 : a >= 10.0 ? 1 : a >= 0.1 || a == 0.0 ? 2 : 3;
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

// The readout goes above the plot (else below it, else into the half away from the pointer):
// outside the plotted area it hides none of the data, least of all the point being read.
ImVec2 readout_position(const PlotFrame& f, ImVec2 size, ImVec2 anchor) {
  const ImVec2 wmin = ImGui::GetWindowPos();
  const ImVec2 wmax(wmin.x + ImGui::GetWindowWidth(), wmin.y + ImGui::GetWindowHeight());
  const float x = std::clamp(anchor.x - 0.5f * size.x, wmin.x, std::max(wmin.x, wmax.x - size.x));
  const float line = ImGui::GetTextLineHeight();
  const float top = f.min.y - 0.5f * line - 1.0f;  // over the plot's title, not its data
  if (top - size.y >= wmin.y) return ImVec2(x, top - size.y);
  const float below = f.max.y + line + 4.0f;  // under the x tick labels
  if (below + size.y <= wmax.y) return ImVec2(x, below);
  const bool pointer_low = anchor.y > 0.5f * (f.min.y + f.max.y);
  return ImVec2(x, pointer_low ? f.min.y + 2.0f : f.max.y - size.y - 2.0f);
}

void draw_readout(const PlotFrame& f, const std::vector<PlotTrace>& traces, const PlotPick& pick,
                  const PlotOptions& options, const PointDescription& describe) {
  const PlotTrace& trace = traces[pick.trace];
  const PlotPoint& p = trace.series->points[pick.point];
  std::string label = describe ? describe(pick.trace, pick.point) : "";
  if (label.empty()) label = trace.series->name + (p.note.empty() ? "" : " \u00b7 " + p.note);
  // The label may already say where the point is (plan steps do, "step 3 of 6").
  std::string values = options.x_name.empty()
                           ? readable(p.y, options.whole_y)
                           : options.x_name + " " + readable(p.x, options.whole_x) + "   " +
                                 readable(p.y, options.whole_y);
  if (!options.y_unit.empty()) values += " " + options.y_unit;
  const float dot = ImGui::GetTextLineHeight(), pad = 5.0f;
  const ImVec2 l = ImGui::CalcTextSize(label.c_str()), v = ImGui::CalcTextSize(values.c_str());
  const ImVec2 size(std::max(l.x + dot, v.x) + 2 * pad, l.y + v.y + 2 * pad);
  const ImVec2 at = readout_position(f, size, f.to_screen(p.x, p.y));
  ImDrawList* dl = ImGui::GetForegroundDrawList();
  dl->AddRectFilled(at, ImVec2(at.x + size.x, at.y + size.y), IM_COL32(20, 22, 26, 240), 3.0f);
  dl->AddRect(at, ImVec2(at.x + size.x, at.y + size.y), muted(0.7f), 3.0f);
  const ImU32 color = ImGui::ColorConvertFloat4ToU32(trace.color);
  dl->AddCircleFilled(ImVec2(at.x + pad + 0.35f * dot, at.y + pad + 0.5f * l.y), 4.0f, color);
  dl->AddText(ImVec2(at.x + pad + dot, at.y + pad), ImGui::GetColorU32(ImGuiCol_Text),
              label.c_str());
  dl->AddText(ImVec2(at.x + pad, at.y + pad + l.y), muted(1.0f), values.c_str());
}

// Rings around the points of the selected event, and around the point under the pointer.
void draw_rings(ImDrawList* dl, const PlotFrame& f, const std::vector<PlotTrace>& traces,
                const PlotOptions& options, const PlotPick& hovered) {
  for (const PlotTrace& t : traces)
    for (const PlotPoint& p : t.series->points)
      if (options.highlighted_event >= 0 && p.event == options.highlighted_event)
        dl->AddCircle(f.to_screen(p.x, p.y), 6.0f, IM_COL32(255, 255, 255, 230), 16, 2.0f);
  if (hovered.trace < 0) return;
  const PlotPoint& p = traces[hovered.trace].series->points[hovered.point];
  dl->AddCircle(f.to_screen(p.x, p.y), 7.0f, IM_COL32(255, 255, 255, 255), 16, 1.5f);
}

std::vector<std::string> legend_items(const std::vector<PlotTrace>& traces,
                                      const std::string& caption) {
  std::vector<std::string> items;
  if (!caption.empty()) items.push_back(caption);
  for (const PlotTrace& t : traces) items.push_back("\u25cf " + t.series->name);
  return items;
}

// The line each item goes on: the next item stays on the line while it fits the width.
std::vector<int> legend_lines(const std::vector<std::string>& items) {
  const float width = ImGui::GetContentRegionAvail().x;
  std::vector<int> lines;
  float used = 0.0f;
  int line = 0;
  for (const std::string& item : items) {
    const float w = ImGui::CalcTextSize(item.c_str()).x;
    if (!lines.empty() && used + kLegendGap + w > width) ++line, used = 0.0f;
    used += (used > 0.0f ? kLegendGap : 0.0f) + w;
    lines.push_back(line);
  }
  return lines;
}

}  // namespace

PlotPick draw_plot(const char* id, const std::vector<PlotTrace>& traces, const PlotOptions& options,
                   const PointDescription& describe) {
  PlotFrame f;
  fit_range(f, traces, options);
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size(std::max(ImGui::GetContentRegionAvail().x, 80.0f),
                    std::max(options.height, 60.0f));
  const float line = ImGui::GetTextLineHeight();
  const float inner_h = size.y - line - 4.0f;
  const AxisTicks yt =
      axis_ticks(f.y0, f.y1, std::clamp(int(inner_h / kMinTickSpace), 2, 6), options.whole_y);
  f.min = ImVec2(origin.x + widest_label(yt) + kTickGap, origin.y + 0.5f * line);
  f.max = ImVec2(origin.x + size.x - 2.0f, origin.y + size.y - line - 4.0f);
  // As many x ticks as their widest label leaves room for.
  const float x_label = ImGui::CalcTextSize(tick_label(f.x1, 1.0).c_str()).x + 18.0f;
  const AxisTicks xt =
      axis_ticks(f.x0, f.x1, std::clamp(int((f.max.x - f.min.x) / x_label), 2, 8), options.whole_x);
  ImGui::InvisibleButton(id, size);
  const bool hovered = ImGui::IsItemHovered();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  draw_axes(dl, f, xt, yt);
  dl->PushClipRect(f.min, f.max, true);
  draw_guides(dl, f, options);
  for (const PlotTrace& t : traces) draw_trace(dl, f, t);
  PlotPick pick = hovered ? nearest_point(f, traces, ImGui::GetIO().MousePos) : PlotPick{};
  draw_rings(dl, f, traces, options, pick);
  dl->PopClipRect();
  if (pick.trace >= 0) {
    ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
    draw_readout(f, traces, pick, options, describe);
    pick.clicked = ImGui::IsItemClicked(ImGuiMouseButton_Left);
  }
  return pick;
}

void draw_legend(const std::vector<PlotTrace>& traces, const std::string& caption) {
  const std::vector<std::string> items = legend_items(traces, caption);
  const std::vector<int> lines = legend_lines(items);
  const size_t first_trace = caption.empty() ? 0 : 1;
  for (size_t i = 0; i < items.size(); ++i) {
    if (i > 0 && lines[i] == lines[i - 1]) ImGui::SameLine(0.0f, kLegendGap);
    const ImVec4 color = i < first_trace ? muted_text_color() : traces[i - first_trace].color;
    ImGui::TextColored(color, "%s", items[i].c_str());
  }
}

}  // namespace stanceplan::gui
