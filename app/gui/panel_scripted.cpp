// PanelApp under --script (panel_script.h): each loop turn completes the action in progress when
// its condition holds (one line printed: the action, the events so far, the search's status) and
// starts the next one. Actions go through the same paths as the user's: the driver's buttons, the
// panel state's requests, and mouse moves that ImGui sees as a real mouse's.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <ostream>
#include <sstream>

#include "app/gui/guide_overlay.h"
#include "app/gui/node_details.h"
#include "app/gui/panel_app_impl.h"
#include "app/gui/script_pointer.h"
#include "app/gui/tree_section.h"

namespace stanceplan::app::panel_detail {

using namespace gui;

std::string PanelApp::status_text() const {
  if (const std::optional<SearchResult>& result = mirror_.result()) {
    if (result->status == PlanStatus::Found) return "plan found";
    return std::string("no plan (") + to_string(result->status) + ")";
  }
  return to_string(driver_.mode());
}

ScriptProgress PanelApp::progress() const {
  ScriptProgress now;
  now.now_s = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
  now.events = mirror_.events().size();
  now.finished = mirror_.finished();
  now.found = now.finished && mirror_.result()->status == PlanStatus::Found;
  now.motion_off = !options_.motion;
  now.motion_done = now.found && (!motion_ || motion_handled_);
  now.stepping =
      driver_.mode() == RunMode::UntilExpansion || driver_.mode() == RunMode::UntilMilestone;
  now.frame_work = !pointer_moves_.empty() || !pending_screenshot_.empty() || state_.open_tab >= 0;
  now.status = status_text();
  return now;
}

// What the view and the inspector show, on one line: "event 31 (milestone, node 12): l_sole on
// floor (loaded, 572 N), r_sole on floor (unloaded)".
std::string PanelApp::shown_summary() const {
  const long shown = shown_event();
  if (shown < 0) return "the initial configuration (no event yet)";
  const SearchEvent& e = mirror_.events()[shown];
  std::ostringstream line;
  if (const TimelinePoint at = timeline_at();
      state_.source == ViewSource::PlanStep && at.sample >= 0)
    line << "motion into step " << at.step << ", sample " << at.sample + 1 << " of "
         << plan_->steps[static_cast<size_t>(at.step)].motion->samples.size() << "; ";
  line << "event " << e.number << " (" << to_string(e.kind) << ", node " << e.node << "): ";
  const NodeDetails details = node_details(scenario_.scene, e);
  if (details.contacts.empty()) line << "no contact";
  for (size_t i = 0; i < details.contacts.size(); ++i) {
    const ContactRow& c = details.contacts[i];
    line << (i > 0 ? ", " : "") << c.name << " (" << (c.loaded ? "loaded" : "unloaded");
    if (c.vertices > 0) line << ", " << std::lround(c.force_W.norm()) << " N";
    line << ")";
  }
  if (const auto aimed = aimed_milestone(scenario_.milestones, e.milestone))
    line << "; " << aimed_caption(*aimed);
  return line.str();
}

void PanelApp::advance_script(std::ostream& out, std::ostream& err) {
  if (!script_ || script_failed_) return;
  try {
    const ScriptProgress now = progress();
    if (const ScriptAction* done = script_->finish(now))
      out << "panel: script " << script_report(*done, now) << "\n" << std::flush;
    if (const ScriptAction* next = script_->start(progress())) {
      carry_out(*next, out);
      // The window closes before another turn: said now.
      if (next->verb == ScriptVerb::Quit)
        out << "panel: script " << script_report(*next, progress()) << "\n" << std::flush;
    }
  } catch (const ScriptFailure& failure) {
    err << "stanceplan: error: " << options_.script << ": " << failure.what() << "\n";
    script_failed_ = true;
    window_.request_close();
  }
}

void PanelApp::carry_out(const ScriptAction& action, std::ostream& out) {
  switch (action.verb) {
    case ScriptVerb::Run:
      return driver_.run();
    case ScriptVerb::Pause:
      return driver_.pause();
    case ScriptVerb::Cancel:
      session_->cancel();
      return;
    case ScriptVerb::Rerun:
      if (mirror_.finished()) rerun();
      return;
    case ScriptVerb::Quit:
      window_.request_close();
      return;
    case ScriptVerb::StepEvent:
      return driver_.step_event();
    case ScriptVerb::StepExpansion:
      return driver_.step_expansion();
    case ScriptVerb::NextMilestone:
      return driver_.next_milestone();
    case ScriptVerb::Speed:
      driver_.set_speed_limit(action.a);
      state_.speed_limit = static_cast<float>(action.a);
      return;
    case ScriptVerb::Wait:
    case ScriptVerb::WaitForPlan:
    case ScriptVerb::WaitForMotion:
    case ScriptVerb::WaitForFailure:
    case ScriptVerb::WaitForEnd:
    case ScriptVerb::WaitForEvent:
      return;  // the runner completes them
    default:
      return carry_out_view_action(action, out);
  }
}

void PanelApp::carry_out_view_action(const ScriptAction& action, std::ostream& out) {
  const int index = static_cast<int>(action.a);
  switch (action.verb) {
    case ScriptVerb::SelectNode:
      if (mirror_.tree().node(index) == nullptr)
        out << "panel: script line " << action.line << ": no node " << index << " yet\n";
      else
        select_node(state_, index);
      return;
    case ScriptVerb::SelectEvent:
      if (index >= static_cast<int>(mirror_.events().size())) {
        out << "panel: script line " << action.line << ": no event " << index << " yet\n";
        return;
      }
      state_.source = ViewSource::Event;
      state_.selected_event = index;
      return;
    case ScriptVerb::Timeline:
      if (!plan_) {
        out << "panel: script line " << action.line << ": no plan yet, no timeline\n";
        return;
      }
      if (action.a >= static_cast<double>(plan_->steps.size() - 1)) {
        show_plan_step(state_, static_cast<int>(plan_->steps.size()) - 1);
      } else {
        show_plan_step(state_, index);  // the whole steps; the rest, the way through the motion
        state_.step_fraction = action.a - std::floor(action.a);
      }
      state_.playing = false;
      return;
    case ScriptVerb::TabInspector:
    case ScriptVerb::TabPlots:
      state_.open_tab = action.verb == ScriptVerb::TabPlots ? 1 : 0;
      return;
    case ScriptVerb::Screenshot:
      pending_screenshot_ = action.path;
      return;
    case ScriptVerb::Print:
      out << "panel: shown: " << shown_summary() << "\n";
      return;
    case ScriptVerb::ExportView:
      state_.export_view = true;
      return;
    case ScriptVerb::ExportStrip:
      state_.export_strip = true;
      return;
    default: {  // orbit, zoom, reset view: the mouse
      // The window's size in ImGui's units (the framebuffer's before the first frame).
      const ImVec2 size = ImGui::GetIO().DisplaySize;
      const PanelLayout layout = size.x > 0.0f ? panel_layout(size.x, size.y)
                                               : panel_layout(float(window_.framebuffer_width()),
                                                              float(window_.framebuffer_height()));
      for (const ScriptedPointer& p :
           scripted_pointer_moves(action, layout.view, state_.reset_button))
        pointer_moves_.push_back(p);
    }
  }
}

}  // namespace stanceplan::app::panel_detail
