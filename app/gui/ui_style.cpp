#include "app/gui/ui_style.h"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "render/render_style.h"

namespace stanceplan::gui {
namespace {

std::string font_file() {
  std::vector<std::string> paths;
  if (const char* path = std::getenv("STANCEPLAN_FONT")) paths.emplace_back(path);
  paths.emplace_back("/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf");
  paths.emplace_back("/usr/share/fonts/TTF/DejaVuSans.ttf");
  for (const std::string& path : paths) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return path;
  }
  return "";
}

}  // namespace

ImVec4 to_imvec(render::Color c) {
  return ImVec4(c.r, c.g, c.b, c.a);
}

void apply_ui_style() {
  ImGui::StyleColorsDark();
  ImGuiStyle& style = ImGui::GetStyle();
  style.WindowRounding = 0.0f;
  style.WindowBorderSize = 0.0f;
  style.FrameRounding = 3.0f;
  style.GrabRounding = 3.0f;
  style.FramePadding = ImVec2(6.0f, 4.0f);
  style.ItemSpacing = ImVec2(8.0f, 5.0f);
  style.WindowPadding = ImVec2(10.0f, 8.0f);
  style.Colors[ImGuiCol_WindowBg] = to_imvec(kPanelBackground);
  style.Colors[ImGuiCol_ChildBg] = to_imvec(kPanelBackground);
  style.Colors[ImGuiCol_Button] = to_imvec(kButton);
  const std::string font = font_file();
  ImGuiIO& io = ImGui::GetIO();
  // Latin-1 and the few symbols the panel uses: dashes and the ellipsis, arrows, the legend's dot.
  static const ImWchar kRanges[] = {0x0020, 0x00FF, 0x2010, 0x2027, 0x2190,
                                    0x2193, 0x25A0, 0x25CF, 0};
  if (font.empty() ||
      io.Fonts->AddFontFromFileTTF(font.c_str(), kFontPixels, nullptr, kRanges) == nullptr)
    io.Fonts->AddFontDefault();
}

ImVec4 status_color(NodeStatus status) {
  switch (status) {
    case NodeStatus::Goal:
      return ImVec4(1.00f, 0.80f, 0.25f, 1.0f);
    case NodeStatus::PlanPath:
      return loaded_color();
    case NodeStatus::NoMotion:
      return ImVec4(0.95f, 0.45f, 0.30f, 1.0f);
    case NodeStatus::Milestone:
      return ImVec4(0.72f, 0.58f, 1.00f, 1.0f);
    case NodeStatus::Expanded:
      return ImVec4(0.45f, 0.70f, 1.00f, 1.0f);
    case NodeStatus::Open:
      return ImVec4(0.80f, 0.82f, 0.85f, 1.0f);
  }
  return ImVec4(1, 1, 1, 1);
}

// The renderer's contact colours, lifted a little for dark backgrounds.
ImVec4 loaded_color() {
  const render::Color c = render::RenderStyle{}.loaded_contact;
  return ImVec4(0.25f + 0.75f * c.r, 0.25f + 0.75f * c.g, 0.25f + 0.75f * c.b, 1.0f);
}
ImVec4 unloaded_color() {
  return to_imvec(render::RenderStyle{}.unloaded_contact);
}
ImVec4 rejected_color() {
  return ImVec4(0.95f, 0.42f, 0.42f, 1.0f);
}
ImVec4 muted_text_color() {
  return ImVec4(0.62f, 0.65f, 0.70f, 1.0f);
}

void section_title(const char* title) {
  ImGui::Spacing();
  ImGui::TextColored(muted_text_color(), "%s", title);
  ImGui::Separator();
}

}  // namespace stanceplan::gui
