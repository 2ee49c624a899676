#pragma once
// A small plot drawn with ImGui's draw list, sized for the inspector column: round tick labels on
// both axes (plot_ticks.h), series as points, lines or a staircase, an optional vertical marker
// and horizontal limit line, and a readout of the point nearest the pointer drawn outside the
// plotted area so that it never hides the data being pointed at. Clicking reports the point.
#include <imgui.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "app/gui/plot_series.h"

namespace stanceplan::gui {

enum class TraceStyle { Points, Lines, LinesAndPoints, Stairs };

struct PlotTrace {
  const PlotSeries* series = nullptr;
  ImVec4 color = ImVec4(1, 1, 1, 1);
  TraceStyle style = TraceStyle::Points;
  bool pickable = true;  // the readout and clicks consider its points
};

struct PlotOptions {
  float height = 120.0f;
  bool whole_x = true;             // x ticks at whole numbers only (events, steps)
  bool whole_y = false;            // likewise for y (iterations, milestones)
  std::string x_name = "event";    // the readout says "event 12"; empty: the label says where
  std::string y_unit;              // the readout says "3.2 ms"
  double y_at_least = 0.0;         // the y range reaches this (a limit line stays in view)
  double marker_x = std::nan("");  // a vertical line there (the current plan step)
  double limit_y = std::nan("");   // a dashed horizontal line there (a bound)
  long highlighted_event = -1;     // points of this event get a ring (the selection)
};

struct PlotPick {
  int trace = -1;  // index in the traces passed; -1: no point under the pointer
  int point = -1;  // index in that trace's series
  bool clicked = false;
};

// The readout's first line for a point; empty: the series' name and the point's note.
using PointDescription = std::function<std::string(int trace, int point)>;

// Takes the full available width and `options.height`; `id` must be unique in the window.
PlotPick draw_plot(const char* id, const std::vector<PlotTrace>& traces, const PlotOptions& options,
                   const PointDescription& describe = {});

// `caption` (muted, may be empty) then "● name" for each trace, wrapped onto as many lines as
// the available width needs.
void draw_legend(const std::vector<PlotTrace>& traces, const std::string& caption = "");

}  // namespace stanceplan::gui
