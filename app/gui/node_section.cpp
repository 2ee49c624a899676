#include "app/gui/node_section.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "app/gui/tree_section.h"
#include "app/gui/ui_style.h"
#include "app/live/event_record.h"

namespace stanceplan::gui {
namespace {

// "8.4 ms", "1.32 s": solver times for people.
std::string people_ms(double ms) {
  char text[32];
  if (ms < 1000.0)
    std::snprintf(text, sizeof(text), "%.1f ms", ms);
  else
    std::snprintf(text, sizeof(text), "%.2f s", ms / 1000.0);
  return text;
}

constexpr ImGuiTableFlags kTable =
    ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchProp;

void draw_solver(const SearchEvent& e) {
  const bool solved = e.status == PostureStatus::Solved;
  ImGui::TextColored(solved ? loaded_color() : rejected_color(), "%s", to_string(e.status));
  ImGui::SameLine();
  // A failed solve is shown at the solver's final iterate: the configuration, forces and
  // residuals below are that iterate's, not a solution's.
  ImGui::TextColored(muted_text_color(), "\u00b7 %d iterations \u00b7 %s \u00b7 %s", e.iterations,
                     people_ms(e.time_ms).c_str(),
                     solved ? "solution" : "shown: the final iterate");
  if (!e.message.empty() && !(solved && e.accepted)) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(muted_text_color(), "%s", e.message.c_str());
    ImGui::PopTextWrapPos();
  }
}

// Every family's worst residual against the solver's constraint tolerance (Ipopt's
// constr_viol_tol, SolverOptions::tolerance): over it in red with the factor.
void draw_residuals(const NodeDetails& d, double tolerance) {
  if (d.residuals.empty()) return;
  char heading[96];
  std::snprintf(heading, sizeof(heading), "Residuals (constraint tolerance %.0e)", tolerance);
  section_title(heading);
  if (!ImGui::BeginTable("residuals", 3, kTable)) return;
  const size_t shown = std::min<size_t>(d.residuals.size(), 8);
  for (size_t i = 0; i < shown; ++i) {
    const ResidualRow& r = d.residuals[i];
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(r.family.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%.1e", r.value);
    ImGui::TableNextColumn();
    if (r.value <= tolerance)
      ImGui::TextColored(loaded_color(), "within");
    else
      ImGui::TextColored(rejected_color(), "%.0f\u00d7 over", r.value / tolerance);
  }
  ImGui::EndTable();
}

void draw_contacts(const NodeDetails& d) {
  section_title("Contacts");
  if (d.contacts.empty()) {
    ImGui::TextColored(muted_text_color(), "none");
    return;
  }
  if (!ImGui::BeginTable("contacts", 3, kTable)) return;
  ImGui::TableSetupColumn("contact", ImGuiTableColumnFlags_WidthStretch, 3.0f);
  ImGui::TableSetupColumn("state", ImGuiTableColumnFlags_WidthStretch, 1.4f);
  ImGui::TableSetupColumn("force |F| (Fz)", ImGuiTableColumnFlags_WidthStretch, 2.0f);
  ImGui::TableHeadersRow();
  for (const ContactRow& c : d.contacts) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(c.name.c_str());
    ImGui::TableNextColumn();
    ImGui::TextColored(c.loaded ? loaded_color() : unloaded_color(),
                       c.loaded ? "loaded" : "unloaded");
    ImGui::TableNextColumn();
    if (c.vertices > 0)
      ImGui::Text("%.0f N (%.0f)", c.force_W.norm(), c.force_W.z());
    else
      ImGui::TextColored(muted_text_color(), "\u2014");
  }
  ImGui::EndTable();
}

// E19: |tau_k| / effort_k, most loaded joints first.
void draw_torques(const NodeDetails& d) {
  std::vector<const TorqueRow*> rows;
  for (const TorqueRow& t : d.torques)
    if (t.effort > 0.0) rows.push_back(&t);
  if (rows.empty()) return;
  std::stable_sort(rows.begin(), rows.end(),
                   [](auto* a, auto* b) { return a->ratio() > b->ratio(); });
  char heading[96];
  std::snprintf(heading, sizeof(heading), "Joint torques / effort limits (worst %.0f %%)",
                100.0 * d.worst_torque_ratio);
  section_title(heading);
  // The figures beside the bar, in the panel's text colour: inside a bar, dark text is lost on
  // the unfilled part and light text on a light fill.
  if (!ImGui::BeginTable("torques", 3, ImGuiTableFlags_SizingStretchProp)) return;
  ImGui::TableSetupColumn("joint", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn("bar", ImGuiTableColumnFlags_WidthStretch, 1.1f);
  ImGui::TableSetupColumn("figures", ImGuiTableColumnFlags_WidthStretch, 0.8f);
  for (const TorqueRow* t : rows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(t->joint.c_str());
    ImGui::TableNextColumn();
    const float ratio = static_cast<float>(std::min(t->ratio(), 1.0));
    const ImVec4 fill = t->ratio() > 0.9   ? rejected_color()
                        : t->ratio() > 0.6 ? unloaded_color()
                                           : loaded_color();
    ImGui::PushStyleColor(ImGuiCol_PlotHistogram, fill);
    ImGui::ProgressBar(ratio, ImVec2(-FLT_MIN, ImGui::GetTextLineHeight()), "");
    ImGui::PopStyleColor();
    ImGui::TableNextColumn();
    ImGui::Text("%.1f / %.0f", t->tau, t->effort);
  }
  ImGui::EndTable();
}

// What the event did, in words: the candidate's change, or what happened to its node.
std::string event_action(const Scene& scene, const SearchEvent& e) {
  const std::string change = app::event_change(scene, e);
  if (!change.empty()) return change;
  switch (e.kind) {
    case SearchEventKind::Expansion:
      return "expansion of node " + std::to_string(e.node);
    case SearchEventKind::Milestone:
      if (skipped_milestone(e)) return "milestone " + std::to_string(e.milestone) + " skipped";
      return "reaches milestone " + std::to_string(e.milestone);
    case SearchEventKind::PlanFound:
      return "goal reached";
    case SearchEventKind::Failure:
      return "no plan";
    case SearchEventKind::MotionFailed:
      return "no motion into node " + std::to_string(e.node);
    case SearchEventKind::Candidate:
      return "initial stance";
  }
  return "";
}

void draw_configuration(const NodeDetails& d) {
  if (d.configuration.empty()) return;
  ImGui::Spacing();
  if (!ImGui::CollapsingHeader("Configuration q")) return;
  if (!ImGui::BeginTable("configuration", 3, kTable)) return;
  for (const ConfigurationRow& row : d.configuration) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextColored(muted_text_color(), "%s", row.entity.c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(row.name.c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%+.4f", row.value);
  }
  ImGui::EndTable();
}

void draw_header(const Scene& scene, const SessionMirror& mirror, const SearchEvent& e,
                 const std::string& title, PanelState& state) {
  ImGui::Text("%s", title.c_str());
  ImGui::SameLine();
  ImGui::TextColored(muted_text_color(), "%s", event_action(scene, e).c_str());
  // The node the event made (accepted candidates) or concerns (expansions, milestones, the goal).
  const int id = e.kind == SearchEventKind::Candidate ? (e.accepted ? e.node : -1) : e.node;
  if (const TreeNode* node = mirror.tree().node(id)) {
    const NodeStatus status = mirror.tree().status(node->id);
    ImGui::TextColored(status_color(status), "%s", to_string(status));
    ImGui::SameLine();
    ImGui::TextColored(muted_text_color(), "\u00b7 node %d \u00b7 depth %d \u00b7 event %d",
                       node->id, node->depth, e.number);
    if (status == NodeStatus::NoMotion) {  // why: its own MotionFailed event, or an ancestor's
      const std::string why = node->motion_failed >= 0
                                  ? mirror.events()[size_t(node->motion_failed)].message
                                  : "the transition into an ancestor has no motion";
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored(status_color(status), "%s", why.c_str());
      ImGui::PopTextWrapPos();
    }
  }
  if (e.parent >= 0) {
    const std::string label = "parent #" + std::to_string(e.parent);
    ImGui::SameLine();
    // On the same line when it fits there (narrow windows), else on the next.
    const float width =
        ImGui::CalcTextSize(label.c_str()).x + 2.0f * ImGui::GetStyle().FramePadding.x;
    if (ImGui::GetContentRegionAvail().x < width) ImGui::NewLine();
    if (ImGui::SmallButton(label.c_str())) select_node(state, e.parent);
  }
}

}  // namespace

void draw_node_section(const Scene& scene, const SessionMirror& mirror, long shown,
                       const std::string& title, double tolerance, PanelState& state) {
  if (shown < 0 || shown >= static_cast<long>(mirror.events().size())) {
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextColored(muted_text_color(),
                       "No event yet: the view shows the initial configuration as the scenario "
                       "states it, before any solve. Run (Space) or Step event (Right arrow).");
    ImGui::PopTextWrapPos();
    return;
  }
  const SearchEvent& e = mirror.events()[shown];
  draw_header(scene, mirror, e, title, state);
  if (e.kind == SearchEventKind::Candidate) draw_solver(e);
  const NodeDetails details = node_details(scene, e);
  draw_contacts(details);
  draw_residuals(details, tolerance);
  draw_torques(details);
  draw_configuration(details);
}

}  // namespace stanceplan::gui
