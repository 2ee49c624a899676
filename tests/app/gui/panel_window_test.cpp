// The panel in a real window: the stanceplan executable under xvfb-run (a virtual X server), as a
// subprocess, scripted to close itself after a number of frames and save the window. The saved
// window must show both halves: ImGui's panel (its window colours, buttons, text) and the 3-D view
// (the renderer's sky and floor, and the robot).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "app/gui/panel_layout.h"
#include "app/gui/panel_palette.h"
#include "render/image/png_io.h"
#include "render/render_style.h"
#include "tests/support/paths.h"
#include "tests/support/xvfb_run.h"

namespace stanceplan {
namespace {

namespace fs = std::filesystem;
using test::find_xvfb_run;
using test::run_in_xvfb;
using test::XvfbRun;

bool near(const std::uint8_t* p, int r, int g, int b, int tolerance) {
  return std::abs(p[0] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
         std::abs(p[2] - b) <= tolerance;
}

int count_in(const render::Image& image, const gui::Rect& r, auto predicate) {
  int n = 0;
  for (int y = int(r.y); y < int(r.y + r.h); ++y)
    for (int x = int(r.x); x < int(r.x + r.w); ++x) n += predicate(image.pixel(x, y)) ? 1 : 0;
  return n;
}

void expect_panel_and_view(const render::Image& shot) {
  ASSERT_EQ(shot.width, 1280);
  ASSERT_EQ(shot.height, 720);
  const gui::PanelLayout layout = gui::panel_layout(1280.0f, 720.0f);
  const auto to_byte = [](float v) { return int(v * 255.0f + 0.5f); };
  const render::Color bg = gui::kPanelBackground;
  // The right column: ImGui windows in the panel's background colour, with text and buttons.
  const gui::Rect column{layout.search.x + 1, 0, layout.search.w - 1, 720};
  const int column_pixels = int(column.w) * 720;
  const int background = count_in(shot, column, [&](const std::uint8_t* p) {
    return near(p, to_byte(bg.r), to_byte(bg.g), to_byte(bg.b), 0);
  });
  EXPECT_GT(background, column_pixels / 4) << "ImGui's window background in the right column";
  const int text = count_in(
      shot, column, [](const std::uint8_t* p) { return p[0] > 200 && p[1] > 200 && p[2] > 200; });
  EXPECT_GT(text, 800) << "light text in the right column";
  // Buttons in the panel's opaque button colour (the enabled ones: the search controls while it
  // runs, the timeline's once the plan is found), in the column and the bar under the view.
  const render::Color button = gui::kButton;
  const auto is_button = [&](const std::uint8_t* p) {
    return near(p, to_byte(button.r), to_byte(button.g), to_byte(button.b), 0);
  };
  EXPECT_GT(count_in(shot, column, is_button) + count_in(shot, layout.bar, is_button), 3000)
      << "buttons";
  // The 3-D view: no panel window over it (a few dark robot pixels may match the colour by chance),
  // the renderer's light sky in its top-right corner ...
  const gui::Rect view = layout.view;
  const int panel_in_view = count_in(shot, view, [&](const std::uint8_t* p) {
    return near(p, to_byte(bg.r), to_byte(bg.g), to_byte(bg.b), 0);
  });
  EXPECT_LT(panel_in_view, int(view.w * view.h) / 1000);
  const render::RenderStyle style;
  const std::uint8_t* sky = shot.pixel(int(view.w) - 6, 4);
  EXPECT_TRUE(near(sky, to_byte(style.background_top.r), to_byte(style.background_top.g),
                   to_byte(style.background_top.b), 12))
      << "sky " << int(sky[0]) << " " << int(sky[1]) << " " << int(sky[2]);
  // ... light floor and sky over most of it, and the robot: darker, shaded pixels in the middle.
  const int light = count_in(
      shot, view, [](const std::uint8_t* p) { return p[0] > 170 && p[1] > 170 && p[2] > 170; });
  EXPECT_GT(light, int(view.w * view.h) / 2) << "floor and sky";
  const gui::Rect middle{view.w * 0.2f, view.h * 0.25f, view.w * 0.6f, view.h * 0.5f};
  const int robot =
      count_in(shot, middle, [](const std::uint8_t* p) { return p[0] + p[1] + p[2] < 3 * 150; });
  EXPECT_GT(robot, 1500) << "the robot in the middle of the view";
}

class PanelWindow : public ::testing::Test {
 protected:
  void SetUp() override {
    if (find_xvfb_run().empty())
      FAIL() << "xvfb-run not found in PATH: the panel test needs a virtual X server. Install the "
                "package xvfb (scripts/bootstrap.sh does).";
  }
};

// The main job with no sub-command opens the panel when a display exists (here Xvfb's).
TEST_F(PanelWindow, TheMainJobOpensThePanelAndSavesTheWindow) {
  const fs::path dir = test::temp_dir("panel_main_job");
  const fs::path shot = dir / "window.png";
  const XvfbRun run = run_in_xvfb(test::source_path("scenarios/humanoid_walk.yaml") +
                                      " --exit-after-frames 30 --screenshot " + shot.string() +
                                      " --out " + (dir / "out").string(),
                                  dir);
  ASSERT_EQ(run.code, 0) << run.log;
  EXPECT_NE(run.log.find("panel: window saved to " + shot.string()), std::string::npos) << run.log;
  EXPECT_NE(run.log.find("search stopped"), std::string::npos) << run.log;
  ASSERT_TRUE(fs::exists(shot)) << run.log;
  expect_panel_and_view(render::read_png(shot.string()));
}

// The panel sub-command: the search runs to the plan, a node is selected, the plan is saved.
TEST_F(PanelWindow, ThePanelCommandRunsTheSearchToThePlan) {
  const fs::path dir = test::temp_dir("panel_command");
  const fs::path shot = dir / "window.png";
  const XvfbRun run = run_in_xvfb("panel " + test::source_path("scenarios/humanoid_walk.yaml") +
                                      " --threads 1 --exit-after-frames 10 --frames-after-search "
                                      "--select-node 3 --screenshot " +
                                      shot.string() + " --out " + (dir / "out").string(),
                                  dir);
  ASSERT_EQ(run.code, 0) << run.log;
  EXPECT_NE(run.log.find("plan found"), std::string::npos) << run.log;
  EXPECT_TRUE(fs::exists(dir / "out" / "plan.json")) << run.log;
  expect_panel_and_view(render::read_png(shot.string()));
}

TEST_F(PanelWindow, ABadScenarioIsNamedAndNoWindowStays) {
  const fs::path dir = test::temp_dir("panel_bad");
  const fs::path bad = dir / "missing.yaml";
  const XvfbRun run = run_in_xvfb("panel " + bad.string() + " --exit-after-frames 5", dir);
  EXPECT_EQ(run.code, 1) << run.log;
  EXPECT_NE(run.log.find(bad.string()), std::string::npos) << run.log;
}

}  // namespace
}  // namespace stanceplan
