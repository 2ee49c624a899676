#include "app/gui/plan_bar_section.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "app/gui/ui_style.h"
#include "app/live/event_record.h"
#include "planner/plan/plan_timeline.h"

namespace stanceplan::gui {
namespace {

constexpr ImGuiWindowFlags kFixedWindow =
    ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings;

// ImGui prints the slider's format with printf: a literal label keeps no '%'.
std::string literal_format(const std::string& text) {
  std::string out;
  for (const char c : text) out += c == '%' ? std::string("%%") : std::string(1, c);
  return out;
}

// Steps only (no motion yet): a slider over whole steps; with motion, a continuous one.
void draw_slider(const Plan& plan, PanelState& state) {
  const int last = static_cast<int>(plan.steps.size()) - 1;
  const std::string label = literal_format(timeline_label(plan, state));
  if (!has_motion(plan)) {
    int step = state.plan_step;
    if (ImGui::SliderInt("##step", &step, 0, last, label.c_str())) {
      show_plan_step(state, step);
      state.playing = false;
    }
    return;
  }
  float position = static_cast<float>(state.plan_step + state.step_fraction);
  if (ImGui::SliderFloat("##position", &position, 0.0f, static_cast<float>(last), label.c_str())) {
    const double p = std::clamp(static_cast<double>(position), 0.0, static_cast<double>(last));
    show_plan_step(state, static_cast<int>(std::floor(p)));
    state.step_fraction = p - std::floor(p);
    state.playing = false;
  }
}

void draw_timeline(const Plan& plan, PanelState& state) {
  const int steps = static_cast<int>(plan.steps.size());
  if (ImGui::Button(state.playing ? "Pause" : "Play", ImVec2(64, 0))) {
    if (!state.playing && state.plan_step >= steps - 1) show_plan_step(state, 0);  // replay
    state.playing = !state.playing;
    state.source = ViewSource::PlanStep;
  }
  ImGui::SameLine();
  const float buttons = 2.0f * 110.0f + 2.0f * ImGui::GetStyle().ItemSpacing.x;
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - buttons);
  draw_slider(plan, state);
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
                           const Plan* plan, int milestones, PanelState& state) {
  ImGui::SetNextWindowPos(ImVec2(area.x, area.y));
  ImGui::SetNextWindowSize(ImVec2(area.w, area.h));
  ImGui::Begin("Plan", nullptr, kFixedWindow);
  const std::optional<SearchResult>& result = mirror.result();
  if (plan && !plan->steps.empty()) {
    draw_timeline(*plan, state);
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
  const double last = static_cast<double>(steps - 1);
  double position = state.plan_step + state.step_fraction +
                    dt_s / std::max(1e-3, static_cast<double>(state.seconds_per_step));
  if (position >= last) {
    position = last;
    state.playing = false;
  }
  state.plan_step = static_cast<int>(std::floor(position));
  state.step_fraction = position - std::floor(position);
}

std::string timeline_label(const Plan& plan, const PanelState& state) {
  const int last = static_cast<int>(plan.steps.size()) - 1;
  const std::string step =
      "step " + std::to_string(state.plan_step) + " of " + std::to_string(last);
  const TimelinePoint at = timeline_point(plan, state.plan_step + state.step_fraction);
  if (at.sample < 0) return "step " + std::to_string(at.step) + " of " + std::to_string(last);
  const size_t n = plan.steps[static_cast<size_t>(at.step)].motion->samples.size();
  return step + ", motion to " + std::to_string(at.step) + ": " + std::to_string(at.sample + 1) +
         " of " + std::to_string(n);
}

}  // namespace stanceplan::gui
