#pragma once
// `stanceplan render PLAN.json --out DIR [--size 1280x720] [--view three-quarter] [--strip
// FILE.png]
// [--gif FILE.gif] [--video FILE.mp4] [--collision-geometry] [--friction-cones] [--eye X Y Z
// --target X Y Z]`: renders every step of a plan (docs/PLAN_FORMAT.md) off-screen to
// DIR/step_000.png, ..., and optionally the figure strip of the sequence, an animated GIF and a
// video (where the build has FFmpeg). Needs no display.
#include <iosfwd>
#include <string>
#include <vector>

namespace CLI {
class App;
}

namespace stanceplan::app {

struct RenderOptions {
  std::string plan;
  std::string out_dir;  // step images; may be empty when --strip or --gif is given
  int width = 1280;
  int height = 720;
  std::string view = "three-quarter";  // front | side | top | three-quarter
  std::string strip;                   // figure strip PNG (empty: none)
  std::string gif;                     // animated GIF (empty: none)
  std::string video;                   // video, MP4 (empty: none)
  double fps = 10.0;                   // GIF of a plan with motion: frames per second
  double step_seconds = 1.0;           // ... and seconds per step
  bool collision_geometry = false;
  bool friction_cones = false;
  std::vector<double> eye;  // explicit camera (3 values each), replaces the view's framing
  std::vector<double> target;
};

// Registers the `render` sub-command on the CLI, parsing into `options`.
void add_render_subcommand(CLI::App& cli, RenderOptions& options);

// 0 on success. Throws InputError naming the file on bad input (unreadable plan, missing URDF,
// unknown view, nothing to write); missing visual meshes are warnings on `err`.
int run_render(const RenderOptions& options, std::ostream& out, std::ostream& err);

}  // namespace stanceplan::app
