#include "app/render_command.h"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>

#include "app/pipeline.h"
#include "planner/util/input_error.h"
#include "render/image/video_file.h"

namespace stanceplan::app {
namespace {

constexpr int kMaxImageSide = 8192;

// "1280x720" -> (1280, 720); false on anything else.
bool parse_size(const std::string& text, int* width, int* height) {
  int w = 0, h = 0;
  char x = 0, extra = 0;
  if (std::sscanf(text.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X'))
    return false;
  if (w < 16 || h < 16 || w > kMaxImageSide || h > kMaxImageSide) return false;
  *width = w;
  *height = h;
  return true;
}

render::SequenceOptions sequence_options(const RenderOptions& options,
                                         const render::PlanView& plan) {
  render::SequenceOptions out = figure_options(plan);
  out.width = options.width;
  out.height = options.height;
  const auto view = render::parse_view(options.view);
  if (!view)
    throw InputError("--view: unknown view \"" + options.view +
                     "\" (expected front, side, top or three-quarter)");
  out.view = *view;
  out.style.collision_geometry = options.collision_geometry;
  out.style.friction_cones = options.friction_cones;
  if (!options.eye.empty() || !options.target.empty()) {
    if (options.eye.size() != 3 || options.target.size() != 3)
      throw InputError("--eye and --target: both are needed, with 3 coordinates each");
    render::Camera camera;
    camera.eye = Eigen::Vector3d(options.eye[0], options.eye[1], options.eye[2]);
    camera.target = Eigen::Vector3d(options.target[0], options.target[1], options.target[2]);
    if ((camera.eye - camera.target).norm() < 1e-6)
      throw InputError("--eye and --target: must differ");
    if ((camera.target - camera.eye).normalized().cross(camera.up).norm() < 1e-3)
      camera.up = Eigen::Vector3d::UnitY();
    out.camera = camera;
  }
  return out;
}

}  // namespace

void add_render_subcommand(CLI::App& cli, RenderOptions& options) {
  CLI::App* cmd = cli.add_subcommand("render",
                                     "Render a plan's steps off-screen (no display needed): "
                                     "DIR/step_000.png, ..., a figure strip and an animated GIF");
  cmd->add_option("plan", options.plan, "plan file (stanceplan/plan@1 or @2 JSON)")->required();
  cmd->add_option("--out", options.out_dir, "folder for the step images (created if missing)");
  cmd->add_option_function<std::string>(
         "--size",
         [&options](const std::string& text) {
           if (!parse_size(text, &options.width, &options.height))
             throw CLI::ValidationError(
                 "--size", "expected WIDTHxHEIGHT between 16 and 8192, found \"" + text + "\"");
         },
         "image size in pixels (default: 1280x720)")
      ->type_name("WxH");
  cmd->add_option("--view", options.view,
                  "camera direction: front | side | top | three-quarter (default)")
      ->check(CLI::IsMember({"front", "side", "top", "three-quarter"}));
  cmd->add_option("--strip", options.strip, "also write the figure strip of the sequence (PNG)");
  cmd->add_option("--gif", options.gif,
                  "also write an animated GIF of the steps (of the motion, when the plan has one)");
  cmd->add_option("--video", options.video,
                  "also write a video (MP4, H.264) of the steps at full size, playing the motion "
                  "at a steady speed (needs a build with FFmpeg's libraries)");
  cmd->add_option("--fps", options.fps, "GIF of a motion, video: frames per second (default 10)")
      ->check(CLI::Range(1.0, 50.0));
  cmd->add_option("--step-seconds", options.step_seconds,
                  "GIF of a motion, video: seconds each step lasts (default 1)")
      ->check(CLI::Range(0.1, 60.0));
  cmd->add_flag("--collision-geometry", options.collision_geometry,
                "draw collision instead of visual geometry");
  cmd->add_flag("--friction-cones", options.friction_cones,
                "draw the friction cone at every loaded contact vertex");
  cmd->add_option("--eye", options.eye, "explicit camera position X Y Z (with --target)")
      ->expected(3);
  cmd->add_option("--target", options.target, "explicit camera target X Y Z (with --eye)")
      ->expected(3);
}

int run_render(const RenderOptions& options, std::ostream& out, std::ostream& err) {
  if (options.out_dir.empty() && options.strip.empty() && options.gif.empty() &&
      options.video.empty())
    throw InputError(
        "render: nothing to write: give --out DIR, --strip FILE.png, --gif FILE.gif or --video "
        "FILE.mp4");
  if (!options.video.empty() && !render::video_support())
    throw InputError(
        "--video: this build has no FFmpeg (install libavcodec-dev libavformat-dev "
        "libswscale-dev, configure and build again)");
  if (options.width < 16 || options.height < 16 || options.width > kMaxImageSide ||
      options.height > kMaxImageSide)
    throw InputError("--size: expected between 16 and 8192 pixels per side");
  const auto finite = [](const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
  };
  if (!finite(options.eye) || !finite(options.target))
    throw InputError("--eye and --target: expected finite coordinates");
  PlanReadOptions read_options;
  read_options.build_collision = false;
  const LoadedPlan plan = read_plan(options.plan, read_options);
  if (plan.plan.steps.empty())
    throw InputError(options.plan + ": steps: the plan has no step to render");
  const render::PlanView view = plan_view(plan);
  render_figures(view, sequence_options(options, view),
                 {options.out_dir, options.strip, options.gif, options.video, options.fps,
                  options.step_seconds},
                 out, err);
  return 0;
}

}  // namespace stanceplan::app
