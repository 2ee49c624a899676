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

void draw_buttons(SearchDriver& driver, bool live, PanelState& state) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float third = (ImGui::GetContentRegionAvail().x - 2.0f * spacing) / 3.0f;
  const RunMode mode = driver.mode();
  if (button("Run", live && mode != RunMode::Running, third)) driver.run();
  ImGui::SameLine();
  if (button("Pause", live && mode != RunMode::Paused, third)) driver.pause();
  ImGui::SameLine();
  if (button("Cancel search", live, third)) state.cancel_search = true;
  if (button("Step event", live, third)) driver.step_event();
  ImGui::SameLine();
  if (button("Step expansion", live, third)) driver.step_expansion();
  ImGui::SameLine();
  if (button("Next milestone", live, third)) driver.next_milestone();
  ImGui::SetNextItemWidth(-FLT_MIN);
  if (ImGui::SliderFloat("##speed", &state.speed_limit, 0.0f, 50.0f,
                         state.speed_limit <= 0.0f ? "speed: no limit" : "speed: %.0f events/s"))
    driver.set_speed_limit(state.speed_limit);
}

void draw_status(const SearchDriver& driver, const SessionMirror& mirror,
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
                     "%zu events \u00b7 %d nodes \u00b7 milestone %d of %d \u00b7 %.1f s",
                     events.size(), static_cast<int>(mirror.tree().nodes().size()), milestone,
                     figures.milestones, figures.elapsed_s);
}

}  // namespace

void draw_controls_section(SearchDriver& driver, const SessionMirror& mirror,
                           const SearchFigures& figures, PanelState& state) {
  draw_buttons(driver, !mirror.finished(), state);
  draw_status(driver, mirror, figures);
}

}  // namespace stanceplan::gui
