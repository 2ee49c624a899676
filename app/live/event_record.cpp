#include "app/live/event_record.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "planner/plan/plan.h"
#include "render/figures/step_caption.h"

namespace stanceplan::app {
namespace {

std::string fixed(double value, int digits) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.*f", digits, value);
  return text;
}

const char* case_name(CandidateCase c) {
  switch (c) {
    case CandidateCase::Add:
      return "add";
    case CandidateCase::Remove:
      return "remove";
    case CandidateCase::None:
      return "none";
  }
  return "none";
}

// Second caption line: what happened.
std::string outcome(const SearchEvent& e, int milestones) {
  switch (e.kind) {
    case SearchEventKind::Expansion:
      return "expanding node " + std::to_string(e.node) + " · target milestone " +
             std::to_string(e.milestone + 1) + " of " + std::to_string(milestones) + " · " +
             std::to_string(e.nodes) + " nodes";
    case SearchEventKind::Candidate: {
      std::string text = std::string(to_string(e.status)) + ", ";
      text += e.accepted ? "accepted as node " + std::to_string(e.node) : "rejected: " + e.message;
      text += " · " + fixed(e.time_ms, 1) + " ms";
      // Which milestone the candidate was aimed at (its step target, E25).
      if (milestones > 0)
        text += " · target milestone " + std::to_string(e.milestone + 1) + " of " +
                std::to_string(milestones);
      return text;
    }
    case SearchEventKind::Milestone:
      if (skipped_milestone(e))
        return "milestone " + std::to_string(e.milestone) + " of " + std::to_string(milestones) +
               " skipped · nearest node " + std::to_string(e.node);
      return "node " + std::to_string(e.node) + " reached milestone " +
             std::to_string(e.milestone) + " of " + std::to_string(milestones);
    case SearchEventKind::PlanFound:
      return "goal stance reached at node " + std::to_string(e.node) + " · " +
             std::to_string(e.nodes) + " nodes";
    case SearchEventKind::Failure:
      return "no plan: " + e.message;
    case SearchEventKind::MotionFailed:
      return "node " + std::to_string(e.node) + " dropped: " + e.message;
  }
  return "";
}

}  // namespace

std::string snapshot_file_name(const SearchEvent& event) {
  char name[64];
  std::snprintf(name, sizeof(name), "event_%05d_%s.png", event.number, to_string(event.kind));
  return name;
}

std::string event_change(const Scene& scene, const SearchEvent& event) {
  if (event.candidate_case == CandidateCase::None) return "";
  PlanStep step;  // render::step_action words a plan step's change; reuse it for candidates
  step.action = case_name(event.candidate_case);
  step.changed = event.changed;
  return render::step_action(scene, step);
}

std::string event_caption(const Scene& scene, const SearchEvent& event, int milestones) {
  std::string title = "Event " + std::to_string(event.number) + " · " + to_string(event.kind);
  const std::string change = event_change(scene, event);
  if (!change.empty()) title += " · " + change;
  const std::string stance =
      event.stance.empty() ? "(none)" : render::stance_summary(scene, event.stance);
  return title + "\n" + outcome(event, milestones) + "\nstance: " + stance;
}

std::string event_json_line(const Scene& scene, const SearchEvent& event, double time_s,
                            const std::string& image) {
  nlohmann::ordered_json j;
  j["number"] = event.number;
  j["kind"] = to_string(event.kind);
  j["node"] = event.node;
  j["parent"] = event.parent;
  auto stance = nlohmann::ordered_json::array();
  for (const Contact& c : event.stance.contacts())
    stance.push_back(
        {scene.surfaces.id(scene.system, c.s1), scene.surfaces.id(scene.system, c.s2)});
  j["stance"] = std::move(stance);
  j["change"] = case_name(event.candidate_case);
  if (event.candidate_case != CandidateCase::None)
    j["changed"] = {scene.surfaces.id(scene.system, event.changed.s1),
                    scene.surfaces.id(scene.system, event.changed.s2)};
  if (event.kind == SearchEventKind::Candidate) {
    j["status"] = to_string(event.status);
    j["accepted"] = event.accepted;
    j["solve_ms"] = event.time_ms;
  }
  if (!event.message.empty()) j["message"] = event.message;
  j["time_s"] = time_s;
  j["milestone"] = event.milestone;
  j["nodes"] = event.nodes;
  j["image"] = image.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(image);
  return j.dump();
}

}  // namespace stanceplan::app
