// `stanceplan render` in-process: the files it writes, and its faults (missing URDF, missing
// visual mesh, bad options).
#include <gtest/gtest.h>

#include <CLI/CLI.hpp>

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "app/render_command.h"
#include "planner/util/input_error.h"
#include "render/image/png_io.h"
#include "render/image/video_file.h"
#include "tests/render/render_fixtures.h"

namespace stanceplan::app {
namespace {

namespace fs = std::filesystem;

std::string read_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void write_text(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The message of the InputError run_render throws, or "" when it does not throw.
std::string input_error_of(const RenderOptions& options) {
  std::ostringstream out, err;
  try {
    run_render(options, out, err);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// The plan file with the robot's URDF path replaced (the plan names it relative to its folder).
std::string with_robot_urdf(const std::string& plan_text, const std::string& urdf) {
  return std::regex_replace(plan_text, std::regex(R"("urdf": "[^"]*humanoid\.urdf")"),
                            "\"urdf\": \"" + urdf + "\"");
}

TEST(RenderCommand, WritesOneImagePerStepAStripAndAGif) {
  const std::string dir = test::fresh_dir("command");
  RenderOptions options;
  options.plan = test::write_humanoid_plan(dir, 3);
  options.out_dir = dir + "/frames";
  options.width = 320;
  options.height = 200;
  options.strip = dir + "/strip.png";
  options.gif = dir + "/steps.gif";
  std::ostringstream out, err;
  ASSERT_EQ(run_render(options, out, err), 0) << err.str();
  EXPECT_EQ(err.str(), "");
  for (const char* name : {"step_000.png", "step_001.png", "step_002.png"}) {
    const std::string path = options.out_dir + "/" + name;
    ASSERT_TRUE(fs::exists(path)) << path;
    EXPECT_EQ(read_text(path).substr(0, 8), "\x89PNG\r\n\x1a\n");
    const render::Image image = render::read_png(path);
    EXPECT_EQ(image.width, 320);
    EXPECT_EQ(image.height, 200);
  }
  EXPECT_FALSE(fs::exists(options.out_dir + "/step_003.png"));
  // The strip: three panels side by side, so wider than tall.
  const render::Image strip = render::read_png(options.strip);
  EXPECT_GT(strip.width, 3 * 250);
  EXPECT_GT(strip.width, strip.height);
  // The GIF: header, logical screen size, trailer.
  const std::string gif = read_text(options.gif);
  ASSERT_GT(gif.size(), 13u);
  EXPECT_EQ(gif.substr(0, 6), "GIF89a");
  EXPECT_EQ(static_cast<unsigned char>(gif[6]) | static_cast<unsigned char>(gif[7]) << 8, 320);
  EXPECT_EQ(static_cast<unsigned char>(gif[8]) | static_cast<unsigned char>(gif[9]) << 8, 200);
  EXPECT_EQ(gif.back(), '\x3B');
  EXPECT_NE(out.str().find("3 images"), std::string::npos);
}

// Mean absolute difference of two frames' RGB (0-255).
double mean_difference(const render::Image& a, const render::Image& b) {
  double sum = 0.0;
  for (size_t i = 0; i < a.rgba.size(); ++i)
    if (i % 4 != 3) sum += std::abs(int(a.rgba[i]) - int(b.rgba[i]));
  return sum / double(a.rgba.size() / 4 * 3);
}

// The video plays the steps at a steady speed: a step without motion is held for step_seconds
// (fps frames), the last one 2.5 s more.
TEST(RenderCommand, TheVideoHoldsEachStepForItsSeconds) {
  if (!render::video_support()) GTEST_SKIP() << "this build has no FFmpeg";
  const std::string dir = test::fresh_dir("command_video");
  RenderOptions options;
  options.plan = test::write_humanoid_plan(dir, 3);
  options.width = 160;
  options.height = 90;
  options.video = dir + "/steps.mp4";
  options.fps = 4.0;
  std::ostringstream out, err;
  ASSERT_EQ(run_render(options, out, err), 0) << err.str();
  EXPECT_NE(out.str().find("render: video of 19 frames ("), std::string::npos) << out.str();
  const std::vector<render::Image> frames = render::read_video(options.video);
  ASSERT_EQ(frames.size(), 19u);  // 2 steps x 4 frames + step 0 + 10 frames of hold
  EXPECT_LT(mean_difference(frames[0], frames[3]), 1.0) << "step 0 held";
  EXPECT_GT(mean_difference(frames[0], frames[4]), 2.0 * mean_difference(frames[0], frames[3]))
      << "then step 1";
}

TEST(RenderCommand, MissingUrdfIsAnErrorNamingTheFile) {
  const std::string dir = test::fresh_dir("missing_urdf");
  const std::string plan = test::write_humanoid_plan(dir, 1);
  write_text(plan, with_robot_urdf(read_text(plan), "no_such_robot.urdf"));
  RenderOptions options;
  options.plan = plan;
  options.out_dir = dir + "/frames";
  EXPECT_NE(input_error_of(options).find("no_such_robot.urdf"), std::string::npos)
      << input_error_of(options);
  EXPECT_FALSE(fs::exists(options.out_dir + "/step_000.png"));
}

TEST(RenderCommand, MissingPlanIsAnErrorNamingTheFile) {
  RenderOptions options;
  options.plan = "/nonexistent/plan.json";
  options.out_dir = test::fresh_dir("missing_plan");
  EXPECT_NE(input_error_of(options).find("/nonexistent/plan.json"), std::string::npos);
}

TEST(RenderCommand, MissingVisualMeshRendersTheRestWithAWarning) {
  const std::string dir = test::fresh_dir("missing_mesh");
  const std::string plan = test::write_humanoid_plan(dir, 1);
  // The humanoid with one more visual on its head: a mesh file that does not exist.
  std::string urdf = read_text(test::source_path("assets/robots/humanoid/humanoid.urdf"));
  const std::string anchor = "<link name=\"waist\">";
  ASSERT_NE(urdf.find(anchor), std::string::npos);
  urdf.replace(
      urdf.find(anchor), anchor.size(),
      anchor + "<visual><geometry><mesh filename=\"meshes/lost_visual.stl\"/></geometry></visual>");
  write_text(dir + "/humanoid.urdf", urdf);
  write_text(plan, with_robot_urdf(read_text(plan), "humanoid.urdf"));
  RenderOptions options;
  options.plan = plan;
  options.out_dir = dir + "/frames";
  options.width = 160;
  options.height = 120;
  std::ostringstream out, err;
  ASSERT_EQ(run_render(options, out, err), 0);
  EXPECT_NE(err.str().find("warning"), std::string::npos) << err.str();
  EXPECT_NE(err.str().find("lost_visual.stl"), std::string::npos) << err.str();
  EXPECT_TRUE(fs::exists(options.out_dir + "/step_000.png"));
}

TEST(RenderCommand, BadOptionsAreInputErrors) {
  const std::string dir = test::fresh_dir("bad_options");
  RenderOptions options;
  options.plan = test::write_humanoid_plan(dir, 1);
  EXPECT_NE(input_error_of(options).find("nothing to write"), std::string::npos);
  options.out_dir = dir + "/frames";
  options.view = "diagonal";
  EXPECT_NE(input_error_of(options).find("diagonal"), std::string::npos);
  options.view = "side";
  options.eye = {1.0, 2.0, 3.0};
  EXPECT_NE(input_error_of(options).find("--target"), std::string::npos);
}

TEST(RenderCommand, CommandLineParsesSizeAndView) {
  CLI::App cli;
  RenderOptions options;
  add_render_subcommand(cli, options);
  const char* argv[] = {"stanceplan", "render",  "plan.json", "--out", "frames",
                        "--size",     "640x360", "--view",    "side"};
  cli.parse(9, argv);
  EXPECT_EQ(options.plan, "plan.json");
  EXPECT_EQ(options.out_dir, "frames");
  EXPECT_EQ(options.width, 640);
  EXPECT_EQ(options.height, 360);
  EXPECT_EQ(options.view, "side");
  CLI::App cli2;
  RenderOptions options2;
  add_render_subcommand(cli2, options2);
  const char* bad[] = {"stanceplan", "render", "plan.json", "--size", "640by360"};
  EXPECT_THROW(cli2.parse(5, bad), CLI::ParseError);
}

}  // namespace
}  // namespace stanceplan::app
