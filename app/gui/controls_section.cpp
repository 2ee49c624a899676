#include "app/gui/controls_section.h"

#include <imgui.h>

#include "app/gui/ui_style.h"

namespace stanceplan::gui {
namespace {

// A button that does nothing (and looks it) when disabled.
bool button(const char* label, bool enabled, float width) {
  ImGui::BeginDisabled(!enabled);
  const bool pressed = ImGui::Button(label, ImVec2(width, 0.0f));
  ImGui::EndDisabled();
  return pressed && enabled;
}

// The long label when it fits the button's width, else the short one (960 x 600 windows).
const char* fitting(const char* long_label, const char* short_label, float width) {
  const float padding = 2.0f * ImGui::GetStyle().FramePadding.x;
  return ImGui::CalcTextSize(long_label).x + padding <= width ? long_label : short_label;
}

// A hover tooltip for the last item (its shortcut, what it does).
void tip(const char* text) {
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}

void draw_search_buttons(SearchDriver& driver, PanelState& state, float third) {
  const RunMode mode = driver.mode();
  if (button("Run", mode != RunMode::Running, third)) driver.run();
  tip("Let the search run (Space toggles run / pause)");
  ImGui::SameLine();
  if (button("Pause", mode != RunMode::Paused, third)) driver.pause();
  tip("Hold the search before its next event (Space)");
  ImGui::SameLine();
  if (button(fitting("Cancel search", "Cancel", third), true, third)) state.cancel_search = true;
  tip("Stop the search between solver iterations; Run again restarts it");
  if (button("Step event", true, third)) driver.step_event();
  tip("Let exactly one event through, then hold (Right arrow)");
  ImGui::SameLine();
  if (button(fitting("Step expansion", "Expansion", third), true, third)) driver.step_expansion();
  tip("Let events through up to and including the next expansion (E)");
  ImGui::SameLine();
  if (button(fitting("Next milestone", "Milestone", third), true, third)) driver.next_milestone();
  tip("Let events through up to and including the next milestone reached (M)");
}

// Once the search has ended: run it again and, without a plan, what came closest.
void draw_after_buttons(const SessionMirror& mirror, PanelState& state, float third) {
  const bool failed = mirror.result()->status != PlanStatus::Found;
  if (button("Run again", true, third)) state.rerun = true;
  tip("A new search from the initial stance, same options (R)");
  ImGui::SameLine();
  if (button(fitting("Closest stance", "Closest", third),
             failed && mirror.result()->closest_node >= 0, third))
    state.show_closest = true;
  tip("Show the node whose stance came closest to the goal");
  ImGui::SameLine();
  if (button(fitting("Export partial", "Partial", third),
             failed && mirror.result()->closest_node >= 0, third))
    state.export_partial = true;
  tip("Write the certified steps from the initial stance to the closest stance "
      "(OUT/partial_plan.json)");
}

void draw_buttons(SearchDriver& driver, const SessionMirror& mirror, PanelState& state) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float third = (ImGui::GetContentRegionAvail().x - 2.0f * spacing) / 3.0f;
  if (mirror.finished())
    draw_after_buttons(mirror, state, third);
  else
    draw_search_buttons(driver, state, third);
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (ImGui::SliderFloat("##speed", &state.speed_limit, 0.0f, 50.0f,
                         state.speed_limit <= 0.0f ? "speed: no limit" : "speed: %.0f events/s"))
    driver.set_speed_limit(state.speed_limit);
  tip("Events per second while running (0: no limit); paced by the panel, not by input");
}

void draw_status_text(const SearchDriver& driver, const SessionMirror& mirror,
                      const SearchFigures& figures) {
  const std::vector<SearchEvent>& events = mirror.events();
  const int milestone = events.empty() ? 0 : events.back().milestone;
  if (mirror.finished()) {
    const SearchResult& r = *mirror.result();
    const bool found = r.status == PlanStatus::Found;
    ImGui::PushStyleColor(ImGuiCol_Text, found ? loaded_color() : rejected_color());
    ImGui::Text("%s",
                found ? "plan found" : (std::string("no plan: ") + to_string(r.status)).c_str());
    ImGui::PopStyleColor();
    ImGui::SameLine();
    ImGui::TextColored(muted_text_color(),
                       "%zu events \u00b7 %d nodes \u00b7 %d solves \u00b7 %.2f s", events.size(),
                       static_cast<int>(r.tree.size()), r.solver_calls, r.wall_time_s);
    return;
  }
  ImGui::Text("%s", to_string(driver.mode()));
  ImGui::SameLine();
  ImGui::TextColored(muted_text_color(),
                     "%zu events \u00b7 %d nodes \u00b7 milestone %d/%d \u00b7 %.1f s",
                     events.size(), static_cast<int>(mirror.tree().nodes().size()), milestone,
                     figures.milestones, figures.elapsed_s);
}

// Progress towards the goal: the node whose stance differs least from the goal's, among those
// the furthest along the guide (the milestone targeted when it was made), and how many contacts
// it still has to change.
void draw_closest(const SessionMirror& mirror, const Stance& goal) {
  int best = -1, best_difference = 0, best_milestone = 0;
  for (const TreeNode& n : mirror.tree().nodes()) {
    const SearchEvent& made_by = mirror.events()[n.event];
    const int d = stance_difference(made_by.stance, goal);
    if (best < 0 || d < best_difference ||
        (d == best_difference && made_by.milestone > best_milestone)) {
      best = n.id;
      best_difference = d;
      best_milestone = made_by.milestone;
    }
  }
  if (best < 0) return;
  ImGui::TextColored(muted_text_color(), "closest to the goal: #%d, %d contact%s to change", best,
                     best_difference, best_difference == 1 ? "" : "s");
}

// The status line wraps in narrow windows (960 x 600).
void draw_status(const SearchDriver& driver, const SessionMirror& mirror,
                 const SearchFigures& figures) {
  ImGui::PushTextWrapPos(0.0f);
  draw_status_text(driver, mirror, figures);
  if (figures.goal != nullptr) draw_closest(mirror, *figures.goal);
  ImGui::PopTextWrapPos();
}

}  // namespace

void draw_controls_section(SearchDriver& driver, const SessionMirror& mirror,
                           const SearchFigures& figures, PanelState& state) {
  draw_buttons(driver, mirror, state);
  draw_status(driver, mirror, figures);
}

}  // namespace stanceplan::gui
