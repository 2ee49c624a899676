// The guide's milestones in the panel (app/gui/guide_overlay.h): the milestone aimed at after an
// event, its caption, and a scripted panel (Xvfb) on a guide-free scenario that says which
// computed milestone the shown event aims at and draws it as a ghost.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "app/gui/guide_overlay.h"
#include "planner/io/scenario.h"
#include "render/image/png_io.h"
#include "render/renderer.h"
#include "tests/render/render_fixtures.h"
#include "tests/support/paths.h"
#include "tests/support/xvfb_run.h"

namespace stanceplan {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

TEST(GuideOverlay, AimsAtTheTargetedMilestoneNumberedFromOne) {
  const std::vector<Eigen::VectorXd> milestones = {Eigen::VectorXd::Constant(3, 1.0),
                                                   Eigen::VectorXd::Constant(3, 2.0)};
  EXPECT_FALSE(gui::aimed_milestone({}, 0).has_value());
  const auto first = gui::aimed_milestone(milestones, 0);
  ASSERT_TRUE(first.has_value());
  EXPECT_EQ(first->q, milestones[0]);
  EXPECT_EQ(gui::aimed_caption(*first), "aiming at milestone 1 of 2 (translucent)");
  // Past the last (the goal reached): still the last.
  EXPECT_EQ(gui::aimed_milestone(milestones, 5)->index, 1);
}

// The ghost itself, off-screen: the walk's robot drawn at q, its ghost 0.6 m to its side. Every
// pixel the ghost changes turns towards its light blue (blue up against red), the ghost covers
// a robot's worth of pixels, and a ghost at q itself changes no pixel outside the robot.
TEST(GuideOverlay, TheGhostTintsWhatItCoversBlueAndNothingElse) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  const Scene& scene = scenario.scene;
  const Eigen::VectorXd& q = scenario.initial_configuration;
  const int robot = scene.system.find_entity("robot");
  ASSERT_GE(robot, 0);
  Eigen::VectorXd ghost_q = q;
  ghost_q[scene.system.offset(robot) + 1] += 0.6;  // the floating root's y
  render::Renderer renderer(320, 240, test::plain_style());
  const render::Camera camera = test::camera_on_x_axis();
  const render::Image plain = renderer.render(scene, q, {}, {}, camera);
  const render::Image ghosted =
      gui::render_with_ghost(renderer, scene, q, {}, {}, ghost_q, camera, "");
  const render::Image self = gui::render_with_ghost(renderer, scene, q, {}, {}, q, camera, "");
  int changed = 0, bluer = 0, changed_off_robot = 0;
  for (int y = 0; y < plain.height; ++y)
    for (int x = 0; x < plain.width; ++x) {
      const std::uint8_t* a = plain.pixel(x, y);
      const std::uint8_t* b = ghosted.pixel(x, y);
      const std::uint8_t* c = self.pixel(x, y);
      const bool background = a[0] == 255 && a[1] == 255 && a[2] == 255;
      if (background && (c[0] != a[0] || c[1] != a[1] || c[2] != a[2])) ++changed_off_robot;
      if (a[0] == b[0] && a[1] == b[1] && a[2] == b[2]) continue;
      ++changed;
      if (b[2] - b[0] > a[2] - a[0]) ++bluer;
    }
  EXPECT_GT(changed, 1500) << "the ghost covers a robot's worth of pixels";
  EXPECT_GE(bluer, changed * 95 / 100) << "what the ghost covers turns light blue";
  EXPECT_EQ(changed_off_robot, 0) << "a ghost at q stays on the robot";
}

// The guide-free walk: its guide is computed before the window opens; the first expansion aims at
// the first computed milestone, and the view draws its ghost (the picture differs from the same
// event without milestones, which the panel of the hand-guided walk cannot show: compared here
// by the ghost's colour, light blue, present in the view).
TEST(GuideOverlay, TheScriptedPanelSaysWhichComputedMilestoneTheEventAimsAt) {
  if (test::find_xvfb_run().empty())
    FAIL() << "xvfb-run not found in PATH: install the package xvfb (scripts/bootstrap.sh does)";
  const fs::path dir = test::temp_dir("guide_overlay");
  std::ofstream(dir / "script.txt")
      << "step event\nprint\nscreenshot " << (dir / "view.png").string() << "\nquit\n";
  const test::XvfbRun r =
      test::run_in_xvfb("panel " + test::source_path("scenarios/guide_free/walk.yaml") +
                            " --threads 1 --paused --out " + (dir / "out").string() + " --script " +
                            (dir / "script.txt").string(),
                        dir);
  ASSERT_EQ(r.code, 0) << r.log;
  EXPECT_THAT(r.log, HasSubstr("; aiming at milestone 1 of ")) << r.log;
  ASSERT_TRUE(fs::exists(dir / "view.png"));
  const render::Image image = render::read_png((dir / "view.png").string());
  int bluish = 0;  // the ghost over the light floor: blue well above red
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[2] > p[0] + 40 && p[2] > 120) ++bluish;
    }
  EXPECT_GT(bluish, 500) << "the ghost is drawn";
}

}  // namespace
}  // namespace stanceplan
