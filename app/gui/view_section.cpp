#include "app/gui/view_section.h"

#include <imgui.h>
#include <imgui_internal.h>  // ImGuiButtonFlags_AllowItemOverlap

#include "app/gui/ui_style.h"

namespace stanceplan::gui {
namespace {

constexpr ImGuiWindowFlags kFixedWindow = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                          ImGuiWindowFlags_NoSavedSettings |
                                          ImGuiWindowFlags_NoBringToFrontOnFocus;

bool handle_mouse(const Rect& area, OrbitCamera& camera) {
  const ImGuiIO& io = ImGui::GetIO();
  bool moved = false;
  if (ImGui::IsItemActive()) {
    if (ImGui::IsMouseDragging(ImGuiMouseButton_Left, 0.0f)) {
      camera.orbit(io.MouseDelta.x, io.MouseDelta.y);
      moved = true;
    } else if (ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f) ||
               ImGui::IsMouseDragging(ImGuiMouseButton_Middle, 0.0f)) {
      camera.pan(io.MouseDelta.x, io.MouseDelta.y, area.h);
      moved = true;
    }
  }
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    camera.zoom(io.MouseWheel);
    moved = true;
  }
  return moved;
}

}  // namespace

bool draw_view_section(const Rect& area, const ViewTexture& texture, OrbitCamera& camera,
                       PanelState& state) {
  ImGui::SetNextWindowPos(ImVec2(area.x, area.y));
  ImGui::SetNextWindowSize(ImVec2(area.w, area.h));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  ImGui::Begin("3-D view", nullptr, kFixedWindow);
  ImGui::PopStyleVar();
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 size(area.w, area.h);
  // The view catches the mouse over its whole area, but lets the buttons drawn over it (Reset
  // view) take the hover and the clicks first: with AllowItemOverlap it is hovered only when it
  // was the hovered item the frame before, and SetItemAllowOverlap lets later items take over.
  ImGui::InvisibleButton("view", size,
                         ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                             ImGuiButtonFlags_MouseButtonMiddle |
                             ImGuiButtonFlags_AllowItemOverlap);
  ImGui::SetItemAllowOverlap();
  const bool moved = handle_mouse(area, camera);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  const ImVec2 corner(origin.x + size.x, origin.y + size.y);
  if (texture.empty()) {
    draw->AddRectFilled(origin, corner, IM_COL32(236, 234, 230, 255));
    draw->AddText(ImVec2(origin.x + 16, origin.y + 16), IM_COL32(60, 64, 70, 255),
                  "rendering the first view\xE2\x80\xA6");
  } else {
    draw->AddImage(texture.id(), origin, corner);
  }
  // The reset button top-right and the mouse hints bottom-right: the caption is top-left and the
  // legend bottom-left in the picture.
  const char* reset = "Reset view";
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::SetCursorScreenPos(
      ImVec2(corner.x - ImGui::CalcTextSize(reset).x - 2.0f * style.FramePadding.x - 12.0f,
             origin.y + 12.0f));
  ImGui::PushStyleColor(ImGuiCol_Button, ImVec4(0.16f, 0.18f, 0.21f, 0.85f));
  ImGui::PushStyleColor(ImGuiCol_ButtonHovered, ImVec4(0.24f, 0.27f, 0.31f, 0.95f));
  if (ImGui::Button(reset)) state.reset_camera = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the framing of the whole task (Home)");
  const ImVec2 reset_min = ImGui::GetItemRectMin(), reset_max = ImGui::GetItemRectMax();
  state.reset_button = {reset_min.x, reset_min.y, reset_max.x - reset_min.x,
                        reset_max.y - reset_min.y};
  ImGui::PopStyleColor(2);
  const char* hint = "drag: orbit \u00b7 right-drag: pan \u00b7 wheel: zoom";
  const ImVec2 hint_size = ImGui::CalcTextSize(hint);
  draw->AddText(ImVec2(corner.x - hint_size.x - 12.0f, corner.y - hint_size.y - 10.0f),
                IM_COL32(90, 96, 104, 255), hint);
  ImGui::End();
  return moved;
}

}  // namespace stanceplan::gui
