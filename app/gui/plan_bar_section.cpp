#include "app/gui/plan_bar_section.h"

#include <imgui.h>

#include <string>

#include "app/gui/ui_style.h"
#include "app/live/event_record.h"

namespace stanceplan::gui {
namespace {

constexpr ImGuiWindowFlags kFixedWindow =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings;

void draw_timeline(const SearchResult& result, PanelState& state) {
  const int steps = static_cast<int>(result.plan.steps.size());
  if (ImGui::Button(state.playing ? "Pause" : "Play", ImVec2(64, 0))) {
    if (!state.playing && state.plan_step >= steps - 1) state.plan_step = 0;  // replay
    state.playing = !state.playing;
    state.play_time_s = 0.0;
    state.source = ViewSource::PlanStep;
  }
  ImGui::SameLine();
  const float buttons = 2.0f * 110.0f + 2.0f * ImGui::GetStyle().ItemSpacing.x;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - buttons);
  int step = state.plan_step;
  if (ImGui::SliderInt("##step", &step, 0, steps - 1,
                       ("step %d of " + std::to_string(steps - 1)).c_str())) {
    state.plan_step = step;
    state.playing = false;
    state.source = ViewSource::PlanStep;
  }
  ImGui::SameLine();
  if (ImGui::Button("Export view", ImVec2(110, 0))) state.export_view = true;
  ImGui::SameLine();
  if (ImGui::Button("Export strip", ImVec2(110, 0))) state.export_strip = true;
}

void draw_message(const Scene& scene, const SessionMirror& mirror, int milestones,
                  const PanelState& state) {
  if (!state.messages.empty()) {
    ImGui::TextColored(muted_text_color(), "%s", state.messages.back().c_str());
    return;
  }
  if (mirror.events().empty()) {
    ImGui::TextColored(muted_text_color(), "solving the initial stance\u2026");
    return;
  }
  // The first line of the snapshot caption of the newest event.
  const std::string caption = app::event_caption(scene, mirror.events().back(), milestones);
  const std::string first = caption.substr(0, caption.find('\n'));
  ImGui::TextColored(muted_text_color(), "%s", first.c_str());
}

}  // namespace

void draw_plan_bar_section(const Rect& area, const Scene& scene, const SessionMirror& mirror,
                           int milestones, PanelState& state) {
  ImGui::SetNextWindowPos(ImVec2(area.x, area.y));
  ImGui::SetNextWindowSize(ImVec2(area.w, area.h));
  ImGui::Begin("Plan", nullptr, kFixedWindow);
  const std::optional<SearchResult>& result = mirror.result();
  if (result && result->status == PlanStatus::Found && !result->plan.steps.empty()) {
    draw_timeline(*result, state);
  } else if (result) {
    ImGui::TextColored(rejected_color(), "No plan (%s): %s", to_string(result->status),
                       result->message.c_str());
  } else {
    ImGui::TextColored(muted_text_color(),
                       "Searching \u2014 the timeline appears when a plan is found");
  }
  draw_message(scene, mirror, milestones, state);
  ImGui::End();
}

void advance_timeline(PanelState& state, int steps, double dt_s) {
  if (!state.playing || steps <= 0) return;
  state.play_time_s += dt_s;
  while (state.play_time_s >= state.seconds_per_step && state.playing) {
    state.play_time_s -= state.seconds_per_step;
    if (state.plan_step + 1 >= steps) {
      state.playing = false;
    } else {
      ++state.plan_step;
    }
  }
}

}  // namespace stanceplan::gui
