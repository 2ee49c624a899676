#include "render/figures/sequence.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "render/figures/annotations.h"
#include "render/figures/step_caption.h"
#include "render/image/text.h"
#include "render/scene/scene_assembly.h"

namespace stanceplan::render {
namespace {

// Size of what moves: the diagonal of the box of the link origins of every robot and object over
// the plan's steps (0 when there is none).
double subject_size(const PlanView& plan) {
  Eigen::AlignedBox3d box;
  for (const PlanStep& step : plan.plan.steps) {
    const SystemPose pose(plan.scene.system, step.q);
    for (int e = 0; e < plan.scene.system.num_entities(); ++e)
      if (plan.scene.system.entity(e).kind != EntityKind::Environment)
        for (const Eigen::Isometry3d& T_WL : pose.data(e).T_WL) box.extend(T_WL.translation());
  }
  return box.isEmpty() ? 0.0 : box.diagonal().norm();
}

// The overlay sizes of RenderStyle are in metres for a humanoid; a smaller subject (a hand, under
// 1 m across) gets them scaled down in proportion, so that arrows and markers do not hide it.
RenderStyle scaled_to_subject(RenderStyle style, double size) {
  const double s = size > 0.0 ? std::clamp(size / 1.0, 0.05, 1.0) : 1.0;
  style.force_max_length *= s;
  style.force_radius *= s;
  style.contact_ring_width *= s;
  style.cone_height *= s;
  style.com_radius *= s;
  style.grid_spacing *= s;
  return style;
}

RenderStyle with_plan_scale(RenderStyle style, const PlanView& plan) {
  style = scaled_to_subject(style, subject_size(plan));
  if (style.force_scale <= 0.0) style.force_scale = plan_force_scale(plan, style.force_max_length);
  style.friction = plan.friction;
  return style;
}

Camera sequence_camera(const PlanView& plan, Renderer& renderer, const SequenceOptions& options) {
  if (options.camera) return *options.camera;
  const double aspect = static_cast<double>(renderer.width()) / renderer.height();
  return frame_box(plan_bounds(plan, renderer.style(), renderer.meshes()), options.view, aspect,
                   frame_margins(options.style));
}

// Width / height of the box seen from the view (an orthographic estimate).
double projected_aspect(const Eigen::AlignedBox3d& box, View view) {
  const Eigen::Vector3d f = -view_direction(view);
  const Eigen::Vector3d right = f.cross(view_up(view)).normalized(), up = right.cross(f);
  double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
  for (int i = 0; i < 8; ++i) {
    const Eigen::Vector3d c = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i));
    x0 = std::min(x0, c.dot(right));
    x1 = std::max(x1, c.dot(right));
    y0 = std::min(y0, c.dot(up));
    y1 = std::max(y1, c.dot(up));
  }
  return (x1 - x0 + 1e-6) / (y1 - y0 + 1e-6);
}

}  // namespace

Eigen::AlignedBox3d plan_bounds(const PlanView& plan, const RenderStyle& style,
                                MeshLibrary& meshes) {
  Eigen::AlignedBox3d box;
  for (const PlanStep& step : plan.plan.steps)
    box.extend(assemble_frame(plan.scene, step.q, step.contacts, {}, style, meshes).bounds());
  if (box.isEmpty() && !plan.plan.steps.empty()) {
    const PlanStep& first = plan.plan.steps.front();
    box = assemble_frame(plan.scene, first.q, first.contacts, {}, style, meshes).bounds(true);
  }
  if (box.isEmpty())
    box = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5));
  return box;
}

double plan_force_scale(const PlanView& plan, double max_length) {
  double largest = 0.0;
  for (const PlanStep& step : plan.plan.steps)
    for (const VertexForce& f : step.forces) largest = std::max(largest, f.force_W.norm());
  return largest > 0.0 ? max_length / largest : 0.0;
}

SequenceRenderer::SequenceRenderer(const PlanView& plan, const SequenceOptions& options,
                                   std::shared_ptr<MeshLibrary> meshes)
    : plan_(plan),
      renderer_(options.width, options.height, with_plan_scale(options.style, plan),
                std::move(meshes)),
      camera_(sequence_camera(plan, renderer_, options)) {}

Image SequenceRenderer::render_step(int step, const std::optional<std::string>& caption) {
  const PlanStep& s = plan_.plan.steps.at(step);
  return renderer_.render(plan_.scene, s.q, s.contacts, s.forces, camera_,
                          caption ? *caption : step_caption(plan_, step));
}

Image SequenceRenderer::render_motion_sample(int step, int sample, const std::string& caption) {
  const PlanStep& s = plan_.plan.steps.at(step);
  std::vector<PlanContact> held;
  for (const Contact& c : plan_.plan.steps.at(step - 1).stance.contacts())
    held.push_back({c, true});
  const MotionSample& m = s.motion->samples.at(sample);
  return renderer_.render(plan_.scene, m.q, held, m.forces, camera_, caption);
}

std::vector<int> key_steps(int num_steps, int max_panels) {
  std::vector<int> steps;
  if (num_steps <= 0) return steps;
  if (num_steps <= max_panels || max_panels < 2) {
    for (int i = 0; i < std::min(num_steps, std::max(max_panels, 1)); ++i) steps.push_back(i);
    return steps;
  }
  for (int k = 0; k < max_panels; ++k)
    steps.push_back(
        static_cast<int>(std::lround(static_cast<double>(k) * (num_steps - 1) / (max_panels - 1))));
  steps.erase(std::unique(steps.begin(), steps.end()), steps.end());
  return steps;
}

std::vector<int> key_steps(int num_steps, int max_panels, std::vector<int> must) {
  if (must.empty() || num_steps <= max_panels || max_panels < 2)
    return key_steps(num_steps, max_panels);
  must.push_back(0);
  must.push_back(num_steps - 1);
  std::erase_if(must, [&](int i) { return i < 0 || i >= num_steps; });
  std::sort(must.begin(), must.end());
  must.erase(std::unique(must.begin(), must.end()), must.end());
  const int m = static_cast<int>(must.size());
  if (m >= max_panels) {
    std::vector<int> steps;
    for (int i : key_steps(m, max_panels)) steps.push_back(must[static_cast<size_t>(i)]);
    return steps;
  }
  // One spare panel at a time to the gap whose sub-intervals would stay the longest.
  std::vector<int> extra(static_cast<size_t>(m - 1), 0);
  for (int spare = max_panels - m; spare > 0; --spare) {
    int best = -1;
    double longest = 0.0;
    for (int g = 0; g + 1 < m; ++g) {
      const int length = must[g + 1] - must[g];
      if (extra[g] + 1 >= length) continue;  // every step of the gap is shown already
      const double spacing = static_cast<double>(length) / (extra[g] + 1);
      if (spacing > longest) longest = spacing, best = g;
    }
    if (best < 0) break;
    ++extra[best];
  }
  std::vector<int> steps;
  for (int g = 0; g < m; ++g) {
    steps.push_back(must[g]);
    if (g + 1 == m) break;
    const double length = must[g + 1] - must[g];
    for (int j = 1; j <= extra[g]; ++j)
      steps.push_back(must[g] + static_cast<int>(std::lround(j * length / (extra[g] + 1))));
  }
  return steps;
}

std::vector<int> first_contact_steps(const Plan& plan) {
  std::vector<int> steps;
  std::set<SurfaceRef> used;
  for (size_t i = 0; i < plan.steps.size(); ++i) {
    const PlanStep& step = plan.steps[i];
    if (i > 0 && step.action == "add" && step.changed && !used.contains(step.changed->s1))
      steps.push_back(static_cast<int>(i));
    for (const Contact& c : step.stance.contacts()) used.insert(c.s1);
  }
  return steps;
}

Image render_strip(const PlanView& plan, StripOptions strip, const SequenceOptions& options,
                   std::shared_ptr<MeshLibrary> meshes, std::vector<std::string>* warnings) {
  if (!meshes) meshes = std::make_shared<MeshLibrary>();
  int max_columns = strip.max_columns;
  if (strip.panel_width <= 0) {
    // Panels shaped like what they show: a walk seen from the side is wide, a stance is tall.
    const double aspect =
        options.camera ? 0.8
                       : projected_aspect(plan_bounds(plan, options.style, *meshes), options.view);
    strip.panel_width =
        static_cast<int>(std::lround(strip.panel_height * std::clamp(1.1 * aspect, 0.7, 1.6)));
    max_columns = std::clamp(strip.max_width / strip.panel_width, 2, strip.max_columns);
  }
  SequenceOptions panel = options;
  panel.width = strip.panel_width;
  panel.height = strip.panel_height;
  panel.style.caption = false;
  panel.style.legend = false;
  SequenceRenderer renderer(plan, panel, meshes);

  const std::vector<int> steps =
      key_steps(renderer.num_steps(), strip.max_panels, first_contact_steps(plan.plan));
  // As few rows as the width allows, then rows filled evenly (8 panels in 4 + 4, not 5 + 3).
  const int count = static_cast<int>(steps.size());
  const int rows = std::max(1, (count + std::max(1, max_columns) - 1) / std::max(1, max_columns));
  const int columns = std::max(1, (count + rows - 1) / rows);
  const float px = std::max(13.0f, std::round(0.042f * strip.panel_height));
  const int margin = static_cast<int>(std::round(1.2f * px)),
            gap = static_cast<int>(std::round(0.8f * px));
  const int title_h = static_cast<int>(std::round(2.6f * px));
  const int label_h = static_cast<int>(std::round(3.2f * px));
  const int width = 2 * margin + columns * strip.panel_width + (columns - 1) * gap;
  const float legend_px = 0.95f * px;
  const int legend_h = legend_height(panel.style, legend_px, width - 2 * margin) + gap;
  const int height =
      2 * margin + title_h + rows * (strip.panel_height + label_h) + (rows - 1) * gap + legend_h;
  Image image(width, height, Color{1, 1, 1, 1});

  const Font* bold = default_font(FontWeight::Bold);
  const Font* regular = default_font(FontWeight::Regular);
  const Color ink = rgb_hex(0x1d232b), soft = rgb_hex(0x4a5360);
  const std::string title =
      !strip.title.empty() ? strip.title
                           : plan_title(plan) + "  —  " + std::to_string(renderer.num_steps()) +
                                 (renderer.num_steps() == 1 ? " step" : " steps");
  if (bold != nullptr)
    bold->draw(image, static_cast<float>(margin), margin + bold->ascent(1.5f * px),
               fit_text(*bold, title, 1.5f * px, static_cast<float>(width - 2 * margin)), 1.5f * px,
               ink);

  for (size_t i = 0; i < steps.size(); ++i) {
    const int column = static_cast<int>(i) % columns, row = static_cast<int>(i) / columns;
    const int x = margin + column * (strip.panel_width + gap);
    const int y = margin + title_h + row * (strip.panel_height + label_h + gap);
    paste(image, renderer.render_step(steps[i], std::string()), x, y);
    fill_rect(image, x, y + strip.panel_height - 1, strip.panel_width, 1, rgb_hex(0xc9ced6));
    if (bold == nullptr || regular == nullptr) continue;
    const PlanStep& step = plan.plan.steps[steps[i]];
    const float baseline =
        static_cast<float>(y + strip.panel_height) + 0.6f * px + bold->ascent(px);
    const float after = bold->draw(image, static_cast<float>(x), baseline,
                                   std::to_string(steps[i]) + "  ", px, ink);
    const float room = static_cast<float>(x + strip.panel_width) - after;
    regular->draw(image, after, baseline,
                  fit_text(*regular, step_action(plan.scene, step), px, room), px, ink);
    regular->draw(image, static_cast<float>(x), baseline + 1.35f * px,
                  fit_text(*regular, step_detail(plan.scene, step), 0.8f * px,
                           static_cast<float>(strip.panel_width)),
                  0.8f * px, soft);
  }
  draw_legend(image, panel.style, legend_px, margin, height - margin - legend_h + gap);
  if (warnings != nullptr) {
    for (std::string& w : renderer.take_warnings()) warnings->push_back(std::move(w));
  }
  return image;
}

}  // namespace stanceplan::render
