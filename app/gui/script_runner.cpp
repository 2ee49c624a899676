#include "app/gui/script_runner.h"

namespace stanceplan::gui {

const ScriptAction* ScriptRunner::start(const ScriptProgress& now) {
  if (active_ || next_ >= actions_.size()) return nullptr;
  active_ = true;
  started_s_ = now.now_s;
  events_before_ = now.events;
  return &actions_[next_++];
}

const ScriptAction* ScriptRunner::finish(const ScriptProgress& now) {
  if (!active_) return nullptr;
  const ScriptAction& action = actions_[next_ - 1];
  if (!complete(action, now)) return nullptr;
  active_ = false;
  return &action;
}

bool ScriptRunner::complete(const ScriptAction& action, const ScriptProgress& now) const {
  const auto cannot = [&](const std::string& why) {
    throw ScriptFailure("line " + std::to_string(action.line) + " \"" + action.text + "\": " + why);
  };
  switch (action.verb) {
    case ScriptVerb::StepEvent:  // the one event let through has arrived
      return now.finished || now.events > events_before_;
    case ScriptVerb::StepExpansion:
    case ScriptVerb::NextMilestone:
      return now.finished || !now.stepping;
    case ScriptVerb::Wait:
      return now.now_s - started_s_ >= action.a;
    case ScriptVerb::WaitForPlan:
      if (now.finished && !now.found) cannot("the search ended without a plan: " + now.status);
      return now.finished;
    case ScriptVerb::WaitForFailure:
      if (now.finished && now.found) cannot("the search found a plan");
      return now.finished;
    case ScriptVerb::WaitForEnd:
      return now.finished;
    case ScriptVerb::WaitForMotion:
      if (now.motion_off) cannot("the panel computes no motion (--no-motion)");
      if (now.finished && !now.found) cannot("the search ended without a plan: " + now.status);
      return now.motion_done;
    case ScriptVerb::WaitForEvent:
      if (now.events >= static_cast<size_t>(action.a)) return true;
      if (now.finished) cannot("the search ended after " + std::to_string(now.events) + " events");
      return false;
    case ScriptVerb::Orbit:
    case ScriptVerb::Zoom:
    case ScriptVerb::ResetView:
    case ScriptVerb::Screenshot:
    case ScriptVerb::TabInspector:
    case ScriptVerb::TabPlots:
      return !now.frame_work;
    default:  // the rest take effect when carried out
      return true;
  }
}

std::string script_report(const ScriptAction& action, const ScriptProgress& now) {
  return "line " + std::to_string(action.line) + " \"" + action.text +
         "\": " + std::to_string(now.events) + " events, " + now.status;
}

}  // namespace stanceplan::gui
