#include "app/gui/tree_section.h"

#include <imgui.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include "app/gui/ui_style.h"
#include "app/live/event_record.h"

namespace stanceplan::gui {
namespace {

bool is_ancestor(const SearchTree& tree, int ancestor, int node) {
  for (int i = node; tree.node(i) != nullptr; i = tree.node(i)->parent)
    if (i == ancestor) return true;
  return false;
}

std::string node_label(const Scene& scene, const SessionMirror& mirror, const TreeNode& n) {
  const std::string change = app::event_change(scene, mirror.events()[n.event]);
  return "#" + std::to_string(n.id) + "  " + (change.empty() ? "initial stance" : change);
}

void draw_rejected(const Scene& scene, const SessionMirror& mirror, const TreeNode& n,
                   PanelState& state) {
  const std::string label =
      std::to_string(n.rejected.size()) + " rejected##r" + std::to_string(n.id);
  ImGui::PushStyleColor(ImGuiCol_Text, rejected_color());
  const bool open = ImGui::TreeNodeEx(label.c_str(), ImGuiTreeNodeFlags_SpanAvailWidth);
  ImGui::PopStyleColor();
  if (!open) return;
  for (size_t index : n.rejected) {
    const SearchEvent& e = mirror.events()[index];
    const std::string why = e.status == PostureStatus::Solved ? e.message : to_string(e.status);
    const std::string item =
        app::event_change(scene, e) + " \u2014 " + why + "##e" + std::to_string(index);
    const bool selected = state.source == ViewSource::Event && state.selected_event == long(index);
    ImGui::PushStyleColor(ImGuiCol_Text, rejected_color());
    if (ImGui::Selectable(item.c_str(), selected)) {
      state.source = ViewSource::Event;
      state.selected_event = static_cast<long>(index);
    }
    ImGui::PopStyleColor();
  }
  ImGui::TreePop();
}

void draw_chain(const Scene& scene, const SessionMirror& mirror, const TreeNode& first,
                PanelState& state);

// One node's line. Its arrow opens what hangs under it: the candidates rejected from it and,
// when it has several children, their branches (indented).
void draw_node(const Scene& scene, const SessionMirror& mirror, const TreeNode& n,
               PanelState& state) {
  const SearchTree& tree = mirror.tree();
  const bool branches = n.children.size() > 1;
  const bool leaf = !branches && n.rejected.empty();
  const bool selected =
      (state.source == ViewSource::Node || state.source == ViewSource::PlanStep) &&
      state.tree_focus == n.id;
  ImGuiTreeNodeFlags flags = ImGuiTreeNodeFlags_OpenOnArrow | ImGuiTreeNodeFlags_SpanAvailWidth;
  if (leaf) flags |= ImGuiTreeNodeFlags_Leaf;
  if (selected) flags |= ImGuiTreeNodeFlags_Selected;
  // A newly focused node (the newest one while following, else the selection) is revealed: the
  // branch points above it open and the list scrolls to it. Otherwise the user's choice stands.
  if (state.reveal_focus && branches && n.id != state.tree_focus &&
      is_ancestor(tree, n.id, state.tree_focus))
    ImGui::SetNextItemOpen(true);
  ImGui::PushStyleColor(ImGuiCol_Text, status_color(tree.status(n.id)));
  const bool open = ImGui::TreeNodeEx(reinterpret_cast<void*>(static_cast<intptr_t>(n.id)), flags,
                                      "%s", node_label(scene, mirror, n).c_str());
  ImGui::PopStyleColor();
  if (ImGui::IsItemClicked() && !ImGui::IsItemToggledOpen()) select_node(state, n.id);
  if (state.reveal_focus && n.id == state.tree_focus) ImGui::SetScrollHereY(0.5f);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "%s \u00b7 depth %d%s", to_string(tree.status(n.id)), n.depth,
        n.milestone >= 0 ? (" \u00b7 milestone " + std::to_string(n.milestone)).c_str() : "");
  if (!open) return;
  if (!n.rejected.empty()) draw_rejected(scene, mirror, n, state);
  if (branches)
    for (int child : n.children) draw_chain(scene, mirror, *tree.node(child), state);
  ImGui::TreePop();
}

// A node and its descendants that are only children, at one indentation: a best-first search
// makes long chains (the walk's plan is 23 nodes deep), which nesting would push off the panel.
void draw_chain(const Scene& scene, const SessionMirror& mirror, const TreeNode& first,
                PanelState& state) {
  for (const TreeNode* n = &first; n != nullptr;) {
    draw_node(scene, mirror, *n, state);
    n = n->children.size() == 1 ? mirror.tree().node(n->children.front()) : nullptr;
  }
}

const char* legend_name(NodeStatus status) {
  switch (status) {
    case NodeStatus::Milestone:
      return "milestone";
    case NodeStatus::PlanPath:
      return "plan";
    default:
      return to_string(status);
  }
}

void draw_legend() {
  const NodeStatus order[] = {NodeStatus::Open, NodeStatus::Expanded, NodeStatus::Milestone,
                              NodeStatus::PlanPath, NodeStatus::Goal};
  for (NodeStatus s : order) {
    ImGui::TextColored(status_color(s), "\u25cf");
    ImGui::SameLine(0.0f, 3.0f);
    ImGui::TextColored(muted_text_color(), "%s", legend_name(s));
    ImGui::SameLine(0.0f, 10.0f);
  }
  ImGui::TextColored(rejected_color(), "\u25cf");
  ImGui::SameLine(0.0f, 3.0f);
  ImGui::TextColored(muted_text_color(), "rejected");
}

}  // namespace

void select_node(PanelState& state, int node) {
  state.source = ViewSource::Node;
  state.selected_node = node;
}

void draw_tree_section(const Scene& scene, const SessionMirror& mirror, PanelState& state) {
  section_title("Search tree");
  draw_legend();
  bool follow = state.source == ViewSource::Latest;
  if (ImGui::Checkbox("Follow the search (view the newest event)", &follow)) {
    if (follow)
      state.source = ViewSource::Latest;
    else
      select_node(state, std::max(state.tree_focus, 0));
  }
  ImGui::BeginChild("tree", ImVec2(0, 0), true);
  ImGui::PushStyleVar(ImGuiStyleVar_IndentSpacing, 11.0f);
  if (const TreeNode* root = mirror.tree().node(0)) draw_chain(scene, mirror, *root, state);
  ImGui::PopStyleVar();
  ImGui::EndChild();
  state.reveal_focus = false;
}

}  // namespace stanceplan::gui
