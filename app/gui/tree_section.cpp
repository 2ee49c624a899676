#include "app/gui/tree_section.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "app/gui/tree_rows.h"
#include "app/gui/ui_style.h"
#include "app/live/event_record.h"

namespace stanceplan::gui {
namespace {

// Horizontal layout of a row: `indent` steps of kLevelStep, the fold marker, the label. A small
// step keeps a 23-node-deep plan within the column; the guide lines (not the step alone) show
// which row is whose parent.
constexpr float kLevelStep = 8.0f;
constexpr float kMarkerWidth = 9.0f;
constexpr float kLabelGap = 3.0f;
constexpr float kLabelRoom = 250.0f;  // width allowed for a label when sizing the scroll area
constexpr float kListPadding = 6.0f;
constexpr float kRowSpacing = 2.0f;  // between rows: dense, as the list holds thousands

// What every row of one frame's list needs to know.
struct ListContext {
  const Scene& scene;
  const SessionMirror& mirror;
  TreeFilter filter;
  PanelState& state;
  float width;      // of every row, so the whole row is clickable and highlighted
  float tooltip_x;  // tooltips end here: left of the panel's column, over the 3-D view
};

std::string change_text(const Scene& scene, const SearchEvent& e) {
  const std::string change = app::event_change(scene, e);
  return change.empty() ? "initial stance" : change;
}

std::string why_rejected(const SearchEvent& e) {
  return e.status == PostureStatus::Solved ? e.message : to_string(e.status);
}

// Built by appending, front to back (GCC 12 warns, wrongly, on "literal" + temporary string).
std::string row_label(const ListContext& c, const TreeRow& row, int index) {
  const std::vector<SearchEvent>& events = c.mirror.events();
  const TreeNode& n = *c.mirror.tree().node(row.node);
  std::string label;
  switch (row.kind) {
    case RowKind::Node:
      if (c.filter == TreeFilter::OnPlan)
        label.append("step ").append(std::to_string(index) + "  ");
      label.append("#").append(std::to_string(n.id)).append("  ");
      label.append(change_text(c.scene, events[n.event]));
      if (c.filter == TreeFilter::Milestones)
        label.append("  \u00b7 milestone ").append(std::to_string(n.milestone));
      break;
    case RowKind::RejectedGroup:
      label.append(std::to_string(n.rejected.size())).append(" rejected");
      break;
    case RowKind::Rejected:
      if (c.filter == TreeFilter::Rejected)
        label.append("from #").append(std::to_string(n.id)).append("  ");
      label.append(change_text(c.scene, events[row.event])).append(" \u2014 ");
      label.append(why_rejected(events[row.event]));
      break;
  }
  return label;
}

ImVec4 row_color(const SearchTree& tree, const TreeRow& row) {
  return row.kind == RowKind::Node ? status_color(tree.status(row.node)) : rejected_color();
}

// The connector lines: a vertical line below each ancestor that has more rows further down, and
// an elbow from the parent's line into this row. x of a level: the centre of its fold marker.
void draw_guides(const RowGuides& g, ImVec2 origin, float row_height) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  ImVec4 faint = muted_text_color();
  faint.w = 0.45f;
  const ImU32 color = ImGui::GetColorU32(faint);
  const auto level_x = [&](int level) {
    return std::floor(origin.x + level * kLevelStep + 0.5f * kMarkerWidth) + 0.5f;
  };
  const float mid = std::floor(origin.y + 0.5f * ImGui::GetFontSize()) + 0.5f;
  for (int level : g.through)
    draw->AddLine(ImVec2(level_x(level), origin.y), ImVec2(level_x(level), origin.y + row_height),
                  color);
  if (g.elbow < 0) return;
  const float x = level_x(g.elbow);
  draw->AddLine(ImVec2(x, origin.y), ImVec2(x, g.elbow_goes_on ? origin.y + row_height : mid),
                color);
  draw->AddLine(ImVec2(x, mid), ImVec2(level_x(g.elbow + 1) - 3.0f, mid), color);
}

// A triangle, right when folded and down when open; a dot for a row with nothing under it.
void draw_marker(const TreeRow& row, ImVec2 at, ImU32 color) {
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 c(at.x + 0.5f * kMarkerWidth, at.y + 0.5f * ImGui::GetFontSize());
  if (!row.foldable) {
    if (row.kind == RowKind::Node) draw->AddCircleFilled(c, 2.0f, color);
    return;
  }
  if (row.folded)
    draw->AddTriangleFilled(ImVec2(c.x - 2.5f, c.y - 4.0f), ImVec2(c.x + 3.5f, c.y),
                            ImVec2(c.x - 2.5f, c.y + 4.0f), color);
  else
    draw->AddTriangleFilled(ImVec2(c.x - 4.0f, c.y - 2.5f), ImVec2(c.x + 4.0f, c.y - 2.5f),
                            ImVec2(c.x, c.y + 3.5f), color);
}

// Beside the panel, over the 3-D view, top-aligned with the row: never over the next rows.
void draw_tooltip(const ListContext& c, const TreeRow& row, float row_y) {
  const SearchTree& tree = c.mirror.tree();
  const TreeNode& n = *tree.node(row.node);
  ImGui::SetNextWindowPos(ImVec2(c.tooltip_x, row_y), ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::BeginTooltip();
  ImGui::PushTextWrapPos(ImGui::GetFontSize() * 24.0f);
  if (row.kind == RowKind::Node) {
    ImGui::TextColored(status_color(tree.status(n.id)), "Node %d \u00b7 %s", n.id,
                       to_string(tree.status(n.id)));
    ImGui::TextUnformatted(change_text(c.scene, c.mirror.events()[n.event]).c_str());
    ImGui::TextColored(muted_text_color(),
                       "depth %d \u00b7 %s \u00b7 %zu children \u00b7 %zu rejected", n.depth,
                       n.parent >= 0 ? ("from #" + std::to_string(n.parent)).c_str() : "root",
                       n.children.size(), n.rejected.size());
    if (n.milestone >= 0) ImGui::Text("reached milestone %d", n.milestone);
  } else if (row.kind == RowKind::RejectedGroup) {
    ImGui::Text("%zu candidates tried from #%d and not accepted", n.rejected.size(), n.id);
  } else {
    const SearchEvent& e = c.mirror.events()[row.event];
    ImGui::TextColored(rejected_color(), "Rejected, tried from #%d (event %d)", n.id, e.number);
    ImGui::TextUnformatted(change_text(c.scene, e).c_str());
    ImGui::TextUnformatted(why_rejected(e).c_str());
  }
  if (row.foldable) ImGui::TextColored(muted_text_color(), "the arrow folds what is under it");
  ImGui::PopTextWrapPos();
  ImGui::EndTooltip();
}

bool row_selected(const PanelState& state, const TreeRow& row) {
  if (row.kind == RowKind::Rejected)
    return state.source == ViewSource::Event && state.selected_event == long(row.event);
  return row.kind == RowKind::Node &&
         (state.source == ViewSource::Node || state.source == ViewSource::PlanStep) &&
         state.tree_focus == row.node;
}

// A click on the marker folds or unfolds; anywhere else it selects (a group row only folds).
void on_click(const TreeRow& row, float marker_x, PanelState& state) {
  const float x = ImGui::GetIO().MouseClickedPos[0].x;
  const bool on_marker = x >= marker_x - 3.0f && x <= marker_x + kMarkerWidth + 3.0f;
  if (row.kind == RowKind::RejectedGroup || (row.foldable && on_marker)) {
    std::vector<bool>& flags =
        row.kind == RowKind::RejectedGroup ? state.tree_rejected_open : state.tree_collapsed;
    set_fold_flag(flags, row.node, !fold_flag(flags, row.node));
    state.tree_focus_row = -1;  // rows above the focus came or went at the user's hand: no follow
  } else if (row.kind == RowKind::Rejected) {
    state.source = ViewSource::Event;
    state.selected_event = static_cast<long>(row.event);
  } else {
    select_node(state, row.node);
  }
}

void draw_row(const ListContext& c, const TreeRow& row, int index, float row_height) {
  ImGui::PushID(row.kind == RowKind::Rejected ? int(row.event) : row.node);
  ImGui::PushID(static_cast<int>(row.kind));
  const ImVec2 top = ImGui::GetCursorScreenPos();
  const bool clicked = ImGui::Selectable("##row", row_selected(c.state, row), 0,
                                         ImVec2(c.width, ImGui::GetFontSize()));
  const bool hovered = ImGui::IsItemHovered();
  ImGui::PopID();
  ImGui::PopID();
  const float x = top.x + row.indent * kLevelStep;
  if (c.filter == TreeFilter::All) draw_guides(row_guides(c.mirror.tree(), row), top, row_height);
  const ImU32 color = ImGui::GetColorU32(row_color(c.mirror.tree(), row));
  draw_marker(row, ImVec2(x, top.y), color);
  ImGui::GetWindowDrawList()->AddText(ImVec2(x + kMarkerWidth + kLabelGap, top.y), color,
                                      row_label(c, row, index).c_str());
  if (clicked) on_click(row, x, c.state);
  if (hovered) draw_tooltip(c, row, top.y);
}

// The list's height in rows, known before its child window begins (its content size is set then).
struct ListHeight {
  float row = 0.0f;    // one row, spacing included
  int visible = 1;     // rows wholly in sight
  float spare = 0.0f;  // blank space under the last row, so that the scroll range is whole rows
};

// Scrolls so that the focused row is in sight with a row to spare above and below; when it is
// not, the row goes to the middle. The scroll is a whole number of rows (see ListHeight), and the
// list's top padding is no more than the spacing between rows, so the top row is never cut.
void keep_in_sight(int row, int row_count, int indent, const ListHeight& h) {
  const int first = static_cast<int>(std::ceil(ImGui::GetScrollY() / h.row - 0.01f));
  const int margin = h.visible >= 5 ? 1 : 0;
  if (row < first + margin || row > first + h.visible - 1 - margin) {
    const int top = std::clamp(row - h.visible / 2, 0, std::max(0, row_count - h.visible));
    ImGui::SetScrollY(top * h.row);
  }
  // Sideways: the row's label in sight, with a few of its ancestors' levels to its left.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float x = indent * kLevelStep;
  const float width = ImGui::GetWindowWidth() - 2.0f * style.WindowPadding.x - style.ScrollbarSize;
  const float label = std::min(200.0f, 0.6f * width);
  if (x < ImGui::GetScrollX() || x + label > ImGui::GetScrollX() + width)
    ImGui::SetScrollX(std::max(0.0f, x - 5.0f * kLevelStep));
}

// Called inside the list; takes effect from the next frame. A newly focused row is brought in
// sight; when the search inserts rows above the focused one, the list scrolls with it (else a
// selection would drift out of sight as the tree grows); otherwise a scroll left between two rows
// by the mouse wheel settles on a whole row.
void scroll_list(int focus, const std::vector<TreeRow>& rows, const ListHeight& h,
                 PanelState& state) {
  const float scroll = ImGui::GetScrollY();
  if (state.reveal_focus && focus >= 0) {
    keep_in_sight(focus, static_cast<int>(rows.size()), rows[focus].indent, h);
  } else if (focus >= 0 && state.tree_focus_row >= 0 && focus != state.tree_focus_row) {
    ImGui::SetScrollY(scroll + (focus - state.tree_focus_row) * h.row);
  } else if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {  // not while dragging the scrollbar
    const float whole = std::round(scroll / h.row) * h.row;
    if (std::fabs(whole - scroll) > 0.5f) ImGui::SetScrollY(whole);
  }
  state.tree_focus_row = focus;
}

// The row to keep in sight: the focused node, or the selected rejected candidate. When revealing,
// the folds above it open first.
int focus_row(const SessionMirror& mirror, TreeFilter filter, PanelState& state,
              std::vector<TreeRow>& rows) {
  const bool event = state.source == ViewSource::Event && state.selected_event >= 0 &&
                     state.selected_event < long(mirror.events().size()) &&
                     mirror.events()[state.selected_event].kind == SearchEventKind::Candidate &&
                     !mirror.events()[state.selected_event].accepted;
  const int node = event ? mirror.events()[state.selected_event].parent : state.tree_focus;
  if (state.reveal_focus && filter == TreeFilter::All) {
    bool changed = expand_ancestors(mirror.tree(), node, state.tree_collapsed);
    if (event && !fold_flag(state.tree_rejected_open, node)) {
      set_fold_flag(state.tree_collapsed, node, false);
      set_fold_flag(state.tree_rejected_open, node, true);
      changed = true;
    }
    if (changed)
      rows = tree_rows(mirror.tree(), filter, state.tree_collapsed, state.tree_rejected_open);
  }
  return event ? rejected_row(rows, size_t(state.selected_event)) : node_row(rows, node);
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

// The colours' meaning as coloured words, wrapped to the column's width: one line where it fits.
void draw_legend() {
  const NodeStatus order[] = {NodeStatus::Open,     NodeStatus::Expanded, NodeStatus::Milestone,
                              NodeStatus::PlanPath, NodeStatus::Goal,     NodeStatus::NoMotion};
  const float right = ImGui::GetCursorScreenPos().x + ImGui::GetContentRegionAvail().x;
  const auto word = [&](const char* text, ImVec4 color, bool first) {
    const float spacing = 9.0f;
    if (!first && ImGui::GetItemRectMax().x + spacing + ImGui::CalcTextSize(text).x <= right)
      ImGui::SameLine(0.0f, spacing);
    ImGui::TextColored(color, "%s", text);
  };
  bool first = true;
  for (NodeStatus s : order) {
    word(legend_name(s), status_color(s), first);
    first = false;
  }
  word("rejected", rejected_color(), false);
}

// One compact line: the title, the follow checkbox, and what the list shows at the right.
void draw_header(PanelState& state) {
  ImGui::Separator();
  ImGui::PushStyleVar(ImGuiStyleVar_FramePadding, ImVec2(4.0f, 1.0f));
  ImGui::AlignTextToFramePadding();
  ImGui::TextColored(muted_text_color(), "Search tree");
  ImGui::SameLine(0.0f, 12.0f);
  bool follow = state.source == ViewSource::Latest;
  if (ImGui::Checkbox("Follow", &follow)) {
    if (follow)
      state.source = ViewSource::Latest;
    else
      select_node(state, std::max(state.tree_focus, 0));
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("view the newest event as the search runs");
  const float combo_width = 120.0f;
  const float after = ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x + 8.0f;
  ImGui::SameLine(std::max(after, ImGui::GetWindowContentRegionMax().x - combo_width));
  ImGui::SetNextItemWidth(combo_width);
  const TreeFilter current = static_cast<TreeFilter>(state.tree_filter);
  if (ImGui::BeginCombo("##tree filter", to_string(current))) {
    for (int i = 0; i < kTreeFilterCount; ++i)
      if (ImGui::Selectable(to_string(static_cast<TreeFilter>(i)), i == state.tree_filter)) {
        state.tree_filter = i;
        state.reveal_focus = true;  // the focus moves to another row: bring it in sight
      }
    ImGui::EndCombo();
  }
  ImGui::PopStyleVar();
}

const char* empty_list_text(TreeFilter filter) {
  switch (filter) {
    case TreeFilter::OnPlan:
      return "no plan yet";
    case TreeFilter::Milestones:
      return "no milestone reached yet";
    case TreeFilter::Rejected:
      return "no candidate rejected yet";
    case TreeFilter::All:
      break;
  }
  return "no node yet";
}

float max_indent(const std::vector<TreeRow>& rows) {
  int deepest = 0;
  for (const TreeRow& r : rows) deepest = std::max(deepest, r.indent);
  return deepest * kLevelStep;
}

}  // namespace

void select_node(PanelState& state, int node) {
  state.source = ViewSource::Node;
  state.selected_node = node;
}

void draw_tree_section(const Scene& scene, const SessionMirror& mirror, PanelState& state) {
  draw_header(state);
  draw_legend();
  for (int i = 0; i < 40; ++i)
    state.tree_filter = std::clamp(state.tree_filter, 0, kTreeFilterCount - 1);
  const TreeFilter filter = static_cast<TreeFilter>(state.tree_filter);
  std::vector<TreeRow> rows =
      tree_rows(mirror.tree(), filter, state.tree_collapsed, state.tree_rejected_open);
  const int focus = focus_row(mirror, filter, state, rows);
  const float tooltip_x = ImGui::GetWindowPos().x - 6.0f;

  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(kListPadding, kRowSpacing));
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing, ImVec2(8.0f, kRowSpacing));
  // The scroll area's size from the rows alone, as the clipper submits only the visible rows:
  // as wide as the deepest row needs (then it scrolls sideways), else the child's own width.
  const ImGuiStyle& style = ImGui::GetStyle();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float needed = max_indent(rows) + kMarkerWidth + kLabelGap + kLabelRoom;
  const bool wide = needed > avail.x - 2.0f * kListPadding - style.ScrollbarSize - 2.0f;
  ListHeight h;
  h.row = ImGui::GetTextLineHeightWithSpacing();
  const float usable = avail.y - 2.0f * kRowSpacing - (wide ? style.ScrollbarSize : 0.0f);
  h.visible = std::max(1, static_cast<int>(usable / h.row));
  if (static_cast<int>(rows.size()) > h.visible) h.spare = usable - h.visible * h.row;
  ImGui::SetNextWindowContentSize(ImVec2(wide ? needed : 0.0f, rows.size() * h.row + h.spare));
  ImGui::BeginChild("tree", ImVec2(0, 0), true, ImGuiWindowFlags_HorizontalScrollbar);
  const float width = std::max(ImGui::GetContentRegionAvail().x, wide ? needed : 0.0f);
  const ListContext context{scene, mirror, filter, state, width, tooltip_x};
  if (rows.empty()) ImGui::TextColored(muted_text_color(), "%s", empty_list_text(filter));
  ImGuiListClipper clipper;
  clipper.Begin(static_cast<int>(rows.size()), h.row);
  while (clipper.Step())
    for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i)
      draw_row(context, rows[i], i, h.row);
  clipper.End();
  scroll_list(focus, rows, h, state);
  ImGui::EndChild();
  ImGui::PopStyleVar(2);
  state.reveal_focus = false;
}

}  // namespace stanceplan::gui
