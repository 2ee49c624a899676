// A plan's figures (app/pipeline.h): its steps, strip and GIF, drawn off-screen from a plan in
// memory or read back from its file.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <ostream>
#include <vector>

#include "app/pipeline.h"
#include "planner/plan/plan_timeline.h"
#include "render/figures/step_caption.h"
#include "render/image/gif_writer.h"
#include "render/image/png_io.h"
#include "render/image/video_file.h"

namespace stanceplan::app {
namespace {

constexpr int kGifMaxWidth = 640;  // GIFs are for slides and READMEs: small files

std::string stem(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

void print_warnings(const std::vector<std::string>& warnings, std::ostream& err) {
  for (const std::string& w : warnings) err << "stanceplan: warning: " << w << "\n";
}

void write_steps(const render::PlanView& plan, const render::SequenceOptions& options,
                 const std::string& dir, const std::shared_ptr<render::MeshLibrary>& meshes,
                 std::ostream& out, std::ostream& err) {
  std::filesystem::create_directories(dir);
  render::SequenceRenderer sequence(plan, options, meshes);
  for (int i = 0; i < sequence.num_steps(); ++i) {
    char name[32];
    std::snprintf(name, sizeof(name), "step_%03d.png", i);
    render::write_png((std::filesystem::path(dir) / name).string(), sequence.render_step(i));
    print_warnings(sequence.take_warnings(), err);
  }
  out << "render: " << sequence.num_steps() << (sequence.num_steps() == 1 ? " image" : " images")
      << " in " << dir << "\n";
}

void write_strip(const render::PlanView& plan, const render::SequenceOptions& options,
                 const std::string& path, const std::shared_ptr<render::MeshLibrary>& meshes,
                 std::ostream& out, std::ostream& err) {
  std::vector<std::string> warnings;
  const render::Image strip =
      render::render_strip(plan, render::StripOptions{}, options, meshes, &warnings);
  print_warnings(warnings, err);
  render::write_png(path, strip);
  out << "render: strip of " << plan.plan.steps.size()
      << (plan.plan.steps.size() == 1 ? " step" : " steps") << " in " << path << "\n";
}

// Frames per step of the timeline played at files.fps, step_seconds each (GIF and video).
int frames_per_step(const FigureFiles& files) {
  return std::max(1, int(std::lround(files.fps * files.step_seconds)));
}

// The motion at a steady speed: step_seconds per step whatever its number of samples, the
// samples picked evenly along the path [step i-1, samples..., step i].
std::vector<render::Image> motion_frames(const render::PlanView& plan,
                                         render::SequenceRenderer& sequence,
                                         const FigureFiles& files) {
  const int per_step = frames_per_step(files);
  std::vector<render::Image> frames{sequence.render_step(0)};
  for (int i = 1; i < sequence.num_steps(); ++i) {
    const std::string caption = render::step_caption(plan, i);
    for (int k = 1; k < per_step; ++k) {
      const TimelinePoint at = timeline_point(plan.plan, i - 1 + double(k) / per_step);
      if (at.sample >= 0) frames.push_back(sequence.render_motion_sample(i, at.sample, caption));
    }
    frames.push_back(sequence.render_step(i));
  }
  return frames;
}

void write_gif(const render::PlanView& plan, render::SequenceOptions options,
               const FigureFiles& files, const std::shared_ptr<render::MeshLibrary>& meshes,
               std::ostream& out, std::ostream& err) {
  const std::string& path = files.gif;
  if (options.width > kGifMaxWidth) {
    options.height = std::max(16, options.height * kGifMaxWidth / options.width);
    options.width = kGifMaxWidth;
  }
  options.style.legend = false;  // too small to read in a GIF; the colours speak for themselves
  render::SequenceRenderer sequence(plan, options, meshes);
  std::vector<render::Image> frames;
  render::GifOptions gif;
  if (has_motion(plan.plan)) {
    frames = motion_frames(plan, sequence, files);
    gif.delay_cs = std::max(2, int(std::lround(100.0 / files.fps)));
  } else {
    for (int i = 0; i < sequence.num_steps(); ++i) frames.push_back(sequence.render_step(i));
  }
  print_warnings(sequence.take_warnings(), err);
  render::write_gif(path, frames, gif);
  out << "render: animated GIF of " << frames.size() << " frames in " << path << "\n";
}

// The video plays the timeline at a steady fps: step_seconds per step, with or without motion (a
// step without one is held), each distinct picture drawn once; the last step stays 2.5 s.
void write_video(const render::PlanView& plan, const render::SequenceOptions& options,
                 const FigureFiles& files, const std::shared_ptr<render::MeshLibrary>& meshes,
                 std::ostream& out, std::ostream& err) {
  render::SequenceRenderer sequence(plan, options, meshes);
  render::VideoWriter video(files.video, options.width, options.height, {files.fps});
  const int per_step = frames_per_step(files);
  const int last = sequence.num_steps() - 1;
  const int frames = last * per_step + 1 + int(std::lround(2.5 * files.fps));
  TimelinePoint drawn{-1, -1};
  render::Image picture;
  for (int k = 0; k < frames; ++k) {
    const TimelinePoint at =
        timeline_point(plan.plan, std::min(double(k) / per_step, double(last)));
    if (!(at == drawn)) {
      picture = at.sample < 0 ? sequence.render_step(at.step)
                              : sequence.render_motion_sample(at.step, at.sample,
                                                              render::step_caption(plan, at.step));
      drawn = at;
    }
    video.add(picture);
  }
  video.finish();
  print_warnings(sequence.take_warnings(), err);
  out << "render: video of " << video.frames() << " frames (" << video.encoder() << ", "
      << files.fps << " fps) in " << files.video << "\n";
}

}  // namespace

render::PlanView plan_view(const LoadedPlan& loaded) {
  return {loaded.scene, loaded.plan, loaded.friction,
          stem(loaded.scenario.empty() ? loaded.file : loaded.scenario)};
}

render::PlanView plan_view(const Scenario& scenario, const Plan& plan) {
  return {scenario.scene, plan, scenario.solver.friction, stem(scenario.file)};
}

render::SequenceOptions figure_options(const render::PlanView& plan) {
  render::SequenceOptions options;
  options.style.friction = plan.friction;
  return options;
}

void render_figures(const render::PlanView& plan, const render::SequenceOptions& options,
                    const FigureFiles& files, std::ostream& out, std::ostream& err) {
  const auto meshes = std::make_shared<render::MeshLibrary>();
  if (!files.steps_dir.empty()) write_steps(plan, options, files.steps_dir, meshes, out, err);
  if (!files.strip.empty()) write_strip(plan, options, files.strip, meshes, out, err);
  if (!files.gif.empty()) write_gif(plan, options, files, meshes, out, err);
  if (!files.video.empty()) write_video(plan, options, files, meshes, out, err);
}

}  // namespace stanceplan::app
