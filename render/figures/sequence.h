#pragma once
// A plan's steps rendered as a sequence: one camera framing and one force scale shared by every
// frame, so that consecutive images line up and arrows compare across steps. Also the figure
// strip (key postures side by side with step labels, a title and one legend).
// Same threading rule as Renderer: use from one thread.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "render/figures/plan_view.h"
#include "render/image/image.h"
#include "render/render_style.h"
#include "render/renderer.h"
#include "render/scene/camera.h"
#include "render/scene/mesh_library.h"

namespace stanceplan::render {

struct SequenceOptions {
  int width = 1280;
  int height = 720;
  View view = View::ThreeQuarter;
  std::optional<Camera> camera;  // replaces the automatic framing
  RenderStyle style;
};

class SequenceRenderer {
 public:
  // Computes the shared framing (the robots, objects and contacts of every step) and the shared
  // force scale (the largest vertex force of the plan is drawn style.force_max_length long).
  // Keeps a copy of the view: the scene and the plan it names must outlive this.
  SequenceRenderer(const PlanView& plan, const SequenceOptions& options,
                   std::shared_ptr<MeshLibrary> meshes = nullptr);

  int num_steps() const { return static_cast<int>(plan_.plan.steps.size()); }
  const Camera& camera() const { return camera_; }
  // The step's image with its caption (step_caption) unless `caption` is given.
  Image render_step(int step, const std::optional<std::string>& caption = std::nullopt);
  // Sample `sample` of the motion into `step` (PlanStep::motion): the previous step's stance,
  // every contact loaded, with the sample's forces.
  Image render_motion_sample(int step, int sample, const std::string& caption);
  std::vector<std::string> take_warnings() { return renderer_.take_warnings(); }

 private:
  PlanView plan_;
  Renderer renderer_;
  Camera camera_;
};

// Framing box of every step of a plan (robots, objects, contact surfaces).
Eigen::AlignedBox3d plan_bounds(const PlanView& plan, const RenderStyle& style,
                                MeshLibrary& meshes);
// Metres per newton drawing the plan's largest vertex force `max_length` long (0 if no force).
double plan_force_scale(const PlanView& plan, double max_length);

struct StripOptions {
  int panel_width = 0;  // 0: from the shape of the plan's framing box (portrait to landscape)
  int panel_height = 360;
  int max_columns = 6;
  int max_width = 2400;  // automatic layouts keep the strip about this wide (fewer columns)
  int max_panels = 8;    // longer plans show evenly spaced key steps, first and last included
  std::string title;     // empty: the scenario's name and the number of steps
};

// Steps shown by a strip of at most max_panels panels: all of them, or evenly spaced ones.
std::vector<int> key_steps(int num_steps, int max_panels);
// The same, always showing the steps in `must` (thinned evenly if there are too many), the other
// panels spread over the gaps between them in proportion to their length.
std::vector<int> key_steps(int num_steps, int max_panels, std::vector<int> must);
// Steps that make a contact with a surface (s1) no earlier stance used: the moments a figure must
// show (the first thigh on the seat, the hand-over to the second arm).
std::vector<int> first_contact_steps(const Plan& plan);

// The figure: a title, the key postures in rows (same framing), each with its step label, and a
// legend. `options.width/height` are ignored (panels have their own size).
Image render_strip(const PlanView& plan, StripOptions strip, const SequenceOptions& options,
                   std::shared_ptr<MeshLibrary> meshes = nullptr,
                   std::vector<std::string>* warnings = nullptr);

}  // namespace stanceplan::render
