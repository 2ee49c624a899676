#include "app/gui/plots_section.h"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <utility>

#include "app/gui/plot_series.h"
#include "app/gui/plot_widget.h"
#include "app/gui/tree_section.h"
#include "app/gui/ui_style.h"

namespace stanceplan::gui {
namespace {

// The inspector column is about 340 x 300 px at 960 x 600: one plot at a time, as tall as the
// tab allows, reads better than two squeezed ones. Below this height tick labels crowd the data.
constexpr float kMinPlotHeight = 90.0f;

enum class SearchPlot { Time, Iterations, Milestones };
enum class PlanPlot { Torque, Forces };

// The series, rebuilt only when events arrive or the plan changes: the panel redraws up to 30
// times a second and a long search holds thousands of candidates.
struct PlotCache {
  const SessionMirror* mirror = nullptr;
  size_t events = 0;
  const Plan* plan = nullptr;
  SearchSeries search;
  PlanSeries plan_series;
};

const PlotCache& cached_series(const Scene& scene, const SessionMirror& mirror, const Plan* plan) {
  static PlotCache cache;
  const bool new_events = cache.mirror != &mirror || cache.events != mirror.events().size();
  if (new_events) cache.search = search_series(mirror.events());
  if (new_events || cache.plan != plan)
    cache.plan_series =
        plan ? plan_series(scene, mirror.events(), mirror.tree(), *plan) : PlanSeries{};
  cache.mirror = &mirror;
  cache.events = mirror.events().size();
  cache.plan = plan;
  return cache;
}

float remaining_height() {
  return std::max(kMinPlotHeight, ImGui::GetContentRegionAvail().y);
}

// The event the view shows now, for the plots to ring; -1 while it follows the search.
long shown_event(const SessionMirror& mirror, const PanelState& state) {
  const SearchTree& tree = mirror.tree();
  if (state.source == ViewSource::Event) return state.selected_event;
  if (state.source == ViewSource::Node && tree.node(state.selected_node))
    return static_cast<long>(tree.node(state.selected_node)->event);
  if (state.source == ViewSource::PlanStep) {
    const std::vector<int> path = tree.plan_path();
    if (state.plan_step >= 0 && state.plan_step < static_cast<int>(path.size()))
      return static_cast<long>(tree.node(path[state.plan_step])->event);
  }
  return -1;
}

// A point of the search plots picked: a node when the event made or reached one (selected as
// the tree selects it), else the rejected candidate itself.
void select_search_event(const SessionMirror& mirror, long index, PanelState& state) {
  const SearchEvent& e = mirror.events().at(static_cast<size_t>(index));
  const bool names_node =
      e.accepted || e.kind == SearchEventKind::Milestone || e.kind == SearchEventKind::PlanFound;
  if (names_node && mirror.tree().node(e.node) != nullptr) {
    select_node(state, e.node);
    return;
  }
  state.source = ViewSource::Event;
  state.selected_event = index;
}

std::string candidate_label(const SearchEvent& e) {
  if (e.accepted) return e.parent < 0 ? "root: node 0" : "accepted: node " + std::to_string(e.node);
  // A solved candidate can still be turned down ("already in the tree"): the message says why.
  const std::string why = e.status == PostureStatus::Solved && !e.message.empty()
                              ? e.message
                              : std::string(to_string(e.status));
  return "rejected: " + why + " (from node " + std::to_string(e.parent) + ")";
}

void draw_candidate_plot(const SessionMirror& mirror, const SearchSeries& s, bool time,
                         PanelState& state) {
  // Rejected first, so that the accepted points (the tree's nodes) are drawn over them.
  const std::vector<PlotTrace> traces = {
      {time ? &s.rejected_time_ms : &s.rejected_iterations, rejected_color()},
      {time ? &s.accepted_time_ms : &s.accepted_iterations, loaded_color()}};
  draw_legend(traces, time ? "ms per solve:" : "iterations per solve:");
  PlotOptions options;
  options.height = remaining_height();
  options.whole_y = !time;
  options.y_unit = time ? "ms" : "iterations";
  options.highlighted_event = shown_event(mirror, state);
  const PlotPick pick = draw_plot("##candidates", traces, options, [&](int t, int i) {
    return candidate_label(mirror.events()[traces[t].series->points[i].event]);
  });
  if (pick.clicked)
    select_search_event(mirror, traces[pick.trace].series->points[pick.point].event, state);
}

void draw_progress_plot(const SessionMirror& mirror, const SearchSeries& s, PanelState& state) {
  const std::vector<PlotTrace> traces = {
      {&s.milestone_target, muted_text_color(), TraceStyle::Stairs, false},
      {&s.milestones_reached, status_color(NodeStatus::Milestone), TraceStyle::Points}};
  draw_legend({traces[1]}, "milestone targeted, by event:");
  PlotOptions options;
  options.height = remaining_height();
  options.whole_y = true;
  options.y_at_least = 1.0;
  options.y_unit = "(milestone)";
  const PlotPick pick = draw_plot("##progress", traces, options, [&](int t, int i) {
    const PlotPoint& p = traces[t].series->points[i];
    return "node " + std::to_string(mirror.events()[p.event].node) + ": " + p.note;
  });
  if (pick.clicked)
    select_search_event(mirror, traces[pick.trace].series->points[pick.point].event, state);
}

void draw_search_plots(const SessionMirror& mirror, const SearchSeries& s, PanelState& state) {
  static SearchPlot shown = SearchPlot::Time;  // a view choice, kept across frames
  int choice = static_cast<int>(shown);
  ImGui::RadioButton("time", &choice, int(SearchPlot::Time));
  ImGui::SameLine();
  ImGui::RadioButton("iterations", &choice, int(SearchPlot::Iterations));
  ImGui::SameLine();
  ImGui::RadioButton("milestones", &choice, int(SearchPlot::Milestones));
  shown = static_cast<SearchPlot>(choice);
  if (mirror.events().empty()) {
    ImGui::TextColored(muted_text_color(), "No solve yet.");
  } else if (shown == SearchPlot::Milestones) {
    draw_progress_plot(mirror, s, state);
  } else {
    draw_candidate_plot(mirror, s, shown == SearchPlot::Time, state);
  }
}

// Contacts get colours of their own, away from the green / orange / red that mean loaded,
// unloaded and rejected elsewhere in the panel.
ImVec4 contact_color(size_t i) {
  static const ImVec4 kColors[] = {
      ImVec4(0.45f, 0.70f, 1.00f, 1.0f), ImVec4(1.00f, 0.85f, 0.35f, 1.0f),
      ImVec4(0.78f, 0.60f, 1.00f, 1.0f), ImVec4(0.40f, 0.90f, 0.90f, 1.0f),
      ImVec4(1.00f, 0.60f, 0.85f, 1.0f), ImVec4(0.85f, 0.85f, 0.85f, 1.0f)};
  return kColors[i % (sizeof kColors / sizeof kColors[0])];
}

// Steps are numbered as the figures number them (render/figures/step_caption.h): 0 is the
// initial stance, "of N" counts the transitions.
std::string step_name(double x, size_t steps) {
  return "step " + std::to_string(static_cast<int>(x)) + " of " +
         std::to_string(static_cast<int>(steps) - 1);
}

PlotOptions plan_options(const PanelState& state, std::string y_unit) {
  PlotOptions options;
  options.y_unit = std::move(y_unit);
  options.height = remaining_height();
  options.x_name = "";  // the readout's label names the step, as the figures do
  options.marker_x = state.plan_step + state.step_fraction;  // where the timeline is
  return options;
}

void pick_plan_step(const std::vector<PlotTrace>& traces, const PlotPick& pick, PanelState& state) {
  if (!pick.clicked) return;
  show_plan_step(state, static_cast<int>(traces[pick.trace].series->points[pick.point].x));
  state.playing = false;  // the step picked stays shown
}

void draw_torque_plot(const PlanSeries& s, PanelState& state) {
  const std::vector<PlotTrace> traces = {
      {&s.worst_torque_ratio, status_color(NodeStatus::Goal), TraceStyle::LinesAndPoints}};
  draw_legend({}, "worst joint per step: |torque| / effort limit");
  PlotOptions options = plan_options(state, "of the limit");
  options.limit_y = 1.0;  // E19: |tau| <= effort
  const PlotPick pick = draw_plot("##torque", traces, options, [&](int t, int i) {
    const PlotPoint& p = traces[t].series->points[i];
    return step_name(p.x, s.nodes.size()) + ": " + (p.note.empty() ? "no limit given" : p.note);
  });
  pick_plan_step(traces, pick, state);
}

void draw_force_plot(const PlanSeries& s, PanelState& state) {
  std::vector<PlotTrace> traces;
  for (size_t i = 0; i < s.contact_force_z.size(); ++i)
    traces.push_back({&s.contact_force_z[i], contact_color(i), TraceStyle::LinesAndPoints});
  draw_legend(traces, "vertical force (N) per step:");
  // The unit moved in by plan_options: assigning "N" to the member here trips GCC 12's
  // -Wrestrict at -O3 (a false positive).
  PlotOptions options = plan_options(state, "N");
  const PlotPick pick = draw_plot("##forces", traces, options, [&](int t, int i) {
    const PlotPoint& p = traces[t].series->points[i];
    return step_name(p.x, s.nodes.size()) + ": " + traces[t].series->name + " (" + p.note + ")";
  });
  pick_plan_step(traces, pick, state);
}

void draw_plan_plots(const Plan* plan, const PlanSeries& s, PanelState& state) {
  static PlanPlot shown = PlanPlot::Torque;  // a view choice, kept across frames
  int choice = static_cast<int>(shown);
  ImGui::RadioButton("torque / effort", &choice, int(PlanPlot::Torque));
  ImGui::SameLine();
  ImGui::RadioButton("contact forces", &choice, int(PlanPlot::Forces));
  shown = static_cast<PlanPlot>(choice);
  if (plan == nullptr || s.nodes.empty()) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(muted_text_color(),
                       "These plots appear once a plan is found: each step's worst joint torque "
                       "against its effort limit, and the force on each contact.");
    ImGui::PopTextWrapPos();
  } else if (shown == PlanPlot::Torque) {
    draw_torque_plot(s, state);
  } else {
    draw_force_plot(s, state);
  }
}

}  // namespace

void draw_plots_section(const Scene& scene, const SessionMirror& mirror, const Plan* plan,
                        PanelState& state) {
  const PlotCache& cache = cached_series(scene, mirror, plan);
  if (!ImGui::BeginTabBar("plots tabs")) return;
  // The plan's plots come forward once, when the plan is found; afterwards the user chooses.
  static const Plan* brought_forward = nullptr;
  const bool bring_plan = plan != nullptr && plan != brought_forward;
  if (bring_plan) brought_forward = plan;
  if (ImGui::BeginTabItem("Search")) {
    draw_search_plots(mirror, cache.search, state);
    ImGui::EndTabItem();
  }
  if (ImGui::BeginTabItem("Plan", nullptr, bring_plan ? ImGuiTabItemFlags_SetSelected : 0)) {
    draw_plan_plots(plan, cache.plan_series, state);
    ImGui::EndTabItem();
  }
  ImGui::EndTabBar();
}

}  // namespace stanceplan::gui
