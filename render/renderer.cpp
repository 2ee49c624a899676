#include "render/renderer.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <unordered_map>

#include "render/figures/annotations.h"
#include "render/gl/gl.h"
#include "render/gl/gl_context.h"
#include "render/gl/gpu_mesh.h"
#include "render/gl/render_targets.h"
#include "render/gl/shader_program.h"
#include "render/gl/shaders.h"
#include "render/image/edge_smoothing.h"
#include "render/scene/contact_overlays.h"
#include "render/scene/lighting.h"
#include "render/scene/scene_assembly.h"

namespace stanceplan::render {
namespace {

using shaders::kFade;
using shaders::kFloorQuad;
using shaders::kGrid;
using shaders::kLit;
using shaders::kShadows;
using shaders::kSpecular;

MeshData ground_quad() {
  return polygon({Eigen::Vector3f(-1, -1, 0), Eigen::Vector3f(1, -1, 0), Eigen::Vector3f(1, 1, 0),
                  Eigen::Vector3f(-1, 1, 0)},
                 Eigen::Vector3f::UnitZ());
}

// Radius of the ground grid around the subject; geometry fades out towards it.
double ground_radius(const Eigen::AlignedBox3d& focus) {
  return std::max(3.5, 2.5 * (focus.max() - focus.min()).head<2>().maxCoeff());
}

// What the shadow map covers: the subject and every other item standing on the visible ground
// near it (a desk, a chair), so that their shadows are whole rather than cut at the map's edge.
// The floor itself (nothing above the ground) casts no shadow on the ground.
Eigen::AlignedBox3d shadow_focus(const DrawList& list, const Eigen::AlignedBox3d& focus,
                                 double ground_z) {
  Eigen::AlignedBox3d near = focus;
  const double reach = 0.5 * ground_radius(focus);
  for (const DrawItem& item : list.items) {
    const Eigen::AlignedBox3d box = item.world_bounds();
    if (box.isEmpty() || box.max().z() <= ground_z + 0.01) continue;
    const Eigen::Vector2d gap = (box.min().head<2>() - focus.max().head<2>())
                                    .cwiseMax(focus.min().head<2>() - box.max().head<2>())
                                    .cwiseMax(0.0);
    if (gap.norm() <= reach) near.extend(box);
  }
  return near;
}

// What every surface program needs to know about the frame.
struct FrameUniforms {
  Eigen::Matrix4f view_projection;
  Eigen::Matrix4f light_matrix;
  Eigen::Vector3f eye_W;
  Lights lights;
  float shadow_texel = 0.0f;
  float shadow_bias = 0.0f;
  Eigen::Vector2f fade_center;
  Eigen::Vector2f fade_range;
  double ground_z = 0.0;
};

// Per item, what the frame decided about it.
struct ItemState {
  bool ghosted = false;    // environment hiding the subject: drawn see-through
  bool on_ground = false;  // environment whose top is the ground (the environment's floor)
};

}  // namespace

struct Renderer::Impl {
  int width;
  int height;
  RenderStyle style;
  std::shared_ptr<MeshLibrary> meshes;
  GlContext context;  // before every GL object: destroyed after them
  std::map<unsigned, std::unique_ptr<ShaderProgram>> surface_programs;  // by shaders::SurfaceFlags
  std::map<const ShaderProgram*, long> program_frame;  // frame whose uniforms each program holds
  std::unique_ptr<ShaderProgram> depth, background;
  std::unique_ptr<RenderTargets> targets;
  unsigned empty_vao = 0;
  MeshData quad_data = ground_quad();
  std::unique_ptr<GpuMesh> quad;
  std::unordered_map<const MeshData*, std::unique_ptr<GpuMesh>> cache;  // library meshes only
  long frame = 0;
  FrameUniforms uniforms;
  const ShaderProgram* in_use = nullptr;

  Impl(int w, int h, const RenderStyle& s, std::shared_ptr<MeshLibrary> m)
      : width(w), height(h), style(s), meshes(m ? std::move(m) : std::make_shared<MeshLibrary>()) {
    if (w <= 0 || h <= 0) throw std::invalid_argument("Renderer: image size must be positive");
    depth = std::make_unique<ShaderProgram>("depth", shaders::depth_vertex().c_str(),
                                            shaders::depth_fragment().c_str());
    background = std::make_unique<ShaderProgram>("background", shaders::background_vertex().c_str(),
                                                 shaders::background_fragment().c_str());
    glGenVertexArrays(1, &empty_vao);
    quad = std::make_unique<GpuMesh>(quad_data);
    create_targets();
    check_gl("Renderer setup");
  }

  ~Impl() {
    context.make_current();
    cache.clear();
    quad.reset();
    targets.reset();
    glDeleteVertexArrays(1, &empty_vao);
    surface_programs.clear();
    depth.reset();
    background.reset();
  }

  void create_targets() {
    // A tiny shadow map when shadows are off: the programs' samplers still want a texture.
    targets =
        std::make_unique<RenderTargets>(width, height, std::max(1, style.samples),
                                        style.shadows ? std::max(256, style.shadow_map_size) : 16);
  }

  const GpuMesh& gpu(const DrawItem& item, std::vector<std::unique_ptr<GpuMesh>>& frame_meshes) {
    if (item.transient) {
      frame_meshes.push_back(std::make_unique<GpuMesh>(*item.mesh));
      return *frame_meshes.back();
    }
    std::unique_ptr<GpuMesh>& slot = cache[item.mesh];
    if (!slot) slot = std::make_unique<GpuMesh>(*item.mesh);
    return *slot;
  }

  unsigned surface_flags(const DrawItem& item, const ItemState& state) const {
    if (!style.lighting || !item.lit) return 0;
    unsigned flags = kLit | (style.shadows ? kShadows : 0u);
    if (!item.environment) return flags | kSpecular;
    return flags | kFade | (state.on_ground && style.grid ? kGrid : 0u);
  }

  // The program of these flags, compiled on first use, in use and holding this frame's uniforms.
  ShaderProgram& use_surface(unsigned flags);

  Image draw(const DrawList& list, const Camera& camera);
  std::vector<ItemState> classify(const DrawList& list, const Eigen::Vector3d& eye,
                                  const Eigen::AlignedBox3d& focus) const;
  Eigen::Matrix4d shadow_pass(const DrawList& list, const std::vector<ItemState>& states,
                              const Lights& lights, const Eigen::AlignedBox3d& focus,
                              std::vector<std::unique_ptr<GpuMesh>>& frame_meshes,
                              double* depth_range);
  enum class Pass { Solid, Decal, Translucent, Xray };
  void draw_pass(const DrawList& list, Pass pass, const std::vector<ItemState>& states,
                 std::vector<std::unique_ptr<GpuMesh>>& frame_meshes, const Eigen::Vector3d& eye);
  // Camera and light matrices, near and far planes (from everything drawn, the ground included)
  // and the fading around the subject: what every surface program reads this frame.
  void prepare_uniforms(const DrawList& list, const Camera& camera,
                        const Eigen::AlignedBox3d& focus, const Lights& lights,
                        const Eigen::Matrix4d& light_matrix, double light_depth_range);
  void draw_background();
  void draw_ground_quad(const Eigen::AlignedBox3d& focus, double z, bool floor);
};

ShaderProgram& Renderer::Impl::use_surface(unsigned flags) {
  std::unique_ptr<ShaderProgram>& program = surface_programs[flags];
  if (!program) {
    const std::string fragment = shaders::surface_fragment(flags);
    program = std::make_unique<ShaderProgram>("surface " + std::to_string(flags),
                                              shaders::mesh_vertex().c_str(), fragment.c_str());
  }
  if (in_use != program.get()) {
    program->use();
    in_use = program.get();
  }
  long& stamp = program_frame[program.get()];
  if (stamp != frame) {
    stamp = frame;
    ShaderProgram& p = *program;
    p.set("u_view_projection", uniforms.view_projection);
    p.set("u_light_matrix", uniforms.light_matrix);
    p.set("u_eye_W", uniforms.eye_W);
    p.set("u_key_dir_W", Eigen::Vector3f(uniforms.lights.key_W.cast<float>()));
    p.set("u_fill_dir_W", Eigen::Vector3f(uniforms.lights.fill_W.cast<float>()));
    p.set("u_shadow_map", 0);
    p.set("u_shadow_texel", uniforms.shadow_texel);
    p.set("u_shadow_bias", uniforms.shadow_bias);
    p.set("u_opacity", 1.0f);
    p.set("u_background_top",
          style.background_gradient ? style.background_top : style.background_bottom);
    p.set("u_background_bottom", style.background_bottom);
    p.set("u_viewport_height", static_cast<float>(height));
    p.set("u_fade_center", uniforms.fade_center);
    p.set("u_fade_range", uniforms.fade_range);
    p.set("u_grid_color", style.grid ? style.grid_color : with_alpha(style.grid_color, 0.0f));
    p.set("u_grid_spacing", static_cast<float>(style.grid_spacing));
    p.set("u_ground_z", static_cast<float>(uniforms.ground_z));
  }
  return *program;
}

std::vector<ItemState> Renderer::Impl::classify(const DrawList& list, const Eigen::Vector3d& eye,
                                                const Eigen::AlignedBox3d& focus) const {
  std::vector<ItemState> states(list.items.size());
  // Only a subject (robots, objects) can be hidden: a scene of environment alone is never ghosted.
  if (style.occluder_opacity < 1.0f && !list.bounds(false).isEmpty()) {
    const std::vector<bool> ghosted = occluding_environment(list, eye, focus);
    for (size_t i = 0; i < states.size(); ++i) states[i].ghosted = ghosted[i];
  }
  if (!list.ground.environment_floor) return states;
  for (size_t i = 0; i < states.size(); ++i) {
    if (!list.items[i].environment) continue;
    const Eigen::AlignedBox3d box = list.items[i].world_bounds();
    states[i].on_ground = !box.isEmpty() && std::abs(box.max().z() - list.ground.z) < 0.01;
  }
  return states;
}

Eigen::Matrix4d Renderer::Impl::shadow_pass(const DrawList& list,
                                            const std::vector<ItemState>& states,
                                            const Lights& lights, const Eigen::AlignedBox3d& focus,
                                            std::vector<std::unique_ptr<GpuMesh>>& frame_meshes,
                                            double* depth_range) {
  const ShadowFrustum frustum = shadow_frustum(lights, shadow_focus(list, focus, list.ground.z),
                                               list.bounds(true), list.ground.z);
  *depth_range = frustum.depth_range;
  const Eigen::Matrix4d& light_matrix = frustum.light_matrix;
  if (!style.shadows) return light_matrix;

  targets->bind_shadow();
  glClear(GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glEnable(GL_POLYGON_OFFSET_FILL);
  glPolygonOffset(1.5f, 2.0f);
  depth->use();
  in_use = depth.get();
  depth->set("u_light_matrix", Eigen::Matrix4f(light_matrix.cast<float>()));
  for (size_t i = 0; i < list.items.size(); ++i) {
    const DrawItem& item = list.items[i];
    // A floor casts no shadow anyone sees, and rasterising it would fill the whole map.
    if (!item.casts_shadow || item.layer != Layer::Solid || states[i].ghosted ||
        states[i].on_ground)
      continue;
    depth->set("u_model", item.T_WM);
    gpu(item, frame_meshes).draw();
  }
  glDisable(GL_POLYGON_OFFSET_FILL);
  return light_matrix;
}

void Renderer::Impl::draw_pass(const DrawList& list, Pass pass,
                               const std::vector<ItemState>& states,
                               std::vector<std::unique_ptr<GpuMesh>>& frame_meshes,
                               const Eigen::Vector3d& eye) {
  struct Entry {
    const DrawItem* item;
    unsigned flags;
    float opacity;
    bool ghost = false;
  };
  std::vector<Entry> entries;
  for (size_t i = 0; i < list.items.size(); ++i) {
    const DrawItem& item = list.items[i];
    const bool ghost = states[i].ghosted;
    const unsigned flags = surface_flags(item, states[i]);
    switch (pass) {
      case Pass::Solid:
        if (item.layer == Layer::Solid && !ghost) entries.push_back({&item, flags, 1.0f});
        break;
      case Pass::Decal:
        if (item.layer == Layer::Decal) entries.push_back({&item, flags, 1.0f});
        break;
      case Pass::Translucent:
        if (item.layer == Layer::Translucent || ghost)
          entries.push_back({&item, flags, ghost ? style.occluder_opacity : 1.0f, ghost});
        break;
      case Pass::Xray:
        if (item.layer == Layer::Solid && item.xray && !ghost)
          entries.push_back(
              {&item, flags, item.xray_opacity >= 0.0f ? item.xray_opacity : style.xray_opacity});
        break;
    }
  }
  if (pass == Pass::Translucent) {
    // Far to near, so that blending composes correctly.
    const auto distance = [&eye](const Entry& e) {
      return (e.item->world_bounds().center() - eye).squaredNorm();
    };
    std::stable_sort(entries.begin(), entries.end(),
                     [&](const Entry& a, const Entry& b) { return distance(a) > distance(b); });
  } else {
    // Fewer program switches; the order within a program is kept.
    std::stable_sort(entries.begin(), entries.end(),
                     [](const Entry& a, const Entry& b) { return a.flags < b.flags; });
  }
  for (const Entry& e : entries) {
    // The subject (everything but the environment) marks its pixels in the stencil buffer, and
    // a see-through occluder is drawn around the subject, never over it: a cutaway.
    glStencilOp(GL_KEEP, GL_KEEP, e.item->environment ? GL_KEEP : GL_REPLACE);
    if (e.ghost)
      glStencilFunc(GL_EQUAL, 0, 0xff);
    else
      glStencilFunc(GL_ALWAYS, 1, 0xff);
    ShaderProgram& program = use_surface(e.flags);
    const GpuMesh& mesh = gpu(*e.item, frame_meshes);
    program.set("u_model", e.item->T_WM);
    const Eigen::Matrix3f A = e.item->T_WM.topLeftCorner<3, 3>();
    program.set("u_normal_matrix",
                std::abs(A.determinant()) > 1e-12f ? Eigen::Matrix3f(A.inverse().transpose()) : A);
    program.set("u_color", e.item->color);
    program.set("u_vertex_colors", e.item->vertex_colors && mesh.has_colors() ? 1 : 0);
    program.set("u_opacity", e.opacity);
    mesh.draw();
  }
  glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
  glStencilFunc(GL_ALWAYS, 0, 0xff);
}

void Renderer::Impl::draw_background() {
  background->use();
  in_use = background.get();
  background->set("u_top", style.background_top);
  background->set("u_bottom", style.background_bottom);
  glBindVertexArray(empty_vao);
  glDrawArrays(GL_TRIANGLES, 0, 3);
}

void Renderer::Impl::draw_ground_quad(const Eigen::AlignedBox3d& focus, double z, bool floor) {
  const double radius = ground_radius(focus);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Eigen::Vector3d(focus.center().x(), focus.center().y(), z);
  const unsigned flags =
      kFloorQuad | kFade | (style.lighting ? kLit : 0u) | (style.shadows ? kShadows : 0u);
  ShaderProgram& program = use_surface(flags);
  program.set("u_model", scaled_transform(T, Eigen::Vector3d(radius, radius, 1.0)));
  program.set("u_normal_matrix", Eigen::Matrix3f(Eigen::Matrix3f::Identity()));
  program.set("u_color", floor ? style.floor_color : with_alpha(style.floor_color, 0.0f));
  quad->draw();
}

void Renderer::Impl::prepare_uniforms(const DrawList& list, const Camera& camera,
                                      const Eigen::AlignedBox3d& focus, const Lights& lights,
                                      const Eigen::Matrix4d& light_matrix,
                                      double light_depth_range) {
  // Near and far planes from everything drawn, the ground included.
  const Eigen::Matrix4d view = camera.view_matrix();
  const double radius = ground_radius(focus);
  Eigen::AlignedBox3d everything = list.bounds(true);
  const double ground_z = list.ground.z;
  everything.extend(
      Eigen::Vector3d(focus.center().x() - radius, focus.center().y() - radius, ground_z));
  everything.extend(
      Eigen::Vector3d(focus.center().x() + radius, focus.center().y() + radius, ground_z));
  Eigen::AlignedBox3d everything_V;
  extend_transformed(everything, view, &everything_V);
  const double far = std::max(-everything_V.min().z() * 1.02, 0.1);
  const double near = std::max(-everything_V.max().z() * 0.95, far / 3000.0);
  const double aspect = static_cast<double>(width) / height;
  uniforms.view_projection = (camera.projection_matrix(aspect, near, far) * view).cast<float>();
  uniforms.light_matrix = light_matrix.cast<float>();
  uniforms.eye_W = camera.eye.cast<float>();
  uniforms.lights = lights;
  uniforms.shadow_texel = 1.0f / static_cast<float>(targets->shadow_size());
  uniforms.shadow_bias = static_cast<float>(0.004 / light_depth_range);
  uniforms.fade_center = focus.center().head<2>().cast<float>();
  uniforms.fade_range =
      Eigen::Vector2f(static_cast<float>(0.6 * radius), static_cast<float>(radius));
  uniforms.ground_z = ground_z;
}

Image Renderer::Impl::draw(const DrawList& list, const Camera& camera) {
  context.make_current();
  ++frame;
  in_use = nullptr;
  std::vector<std::unique_ptr<GpuMesh>> frame_meshes;
  Eigen::AlignedBox3d focus = list.bounds(false);
  if (focus.isEmpty()) focus = list.bounds(true);
  if (focus.isEmpty())
    focus = Eigen::AlignedBox3d(Eigen::Vector3d::Constant(-0.5), Eigen::Vector3d::Constant(0.5));
  const std::vector<ItemState> states = classify(list, camera.eye, focus);
  const Lights lights = lights_for(camera);
  double light_depth_range = 1.0;
  const Eigen::Matrix4d light_matrix =
      shadow_pass(list, states, lights, focus, frame_meshes, &light_depth_range);

  prepare_uniforms(list, camera, focus, lights, light_matrix, light_depth_range);

  targets->bind_scene();
  const Color bg = style.background_bottom;
  glClearColor(bg.r, bg.g, bg.b, 1.0f);
  glDepthMask(GL_TRUE);
  glStencilMask(0xff);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  // The stencil test costs every fragment some work on llvmpipe: only frames with a see-through
  // occluder need it.
  if (std::any_of(states.begin(), states.end(), [](const ItemState& s) { return s.ghosted; }))
    glEnable(GL_STENCIL_TEST);
  else
    glDisable(GL_STENCIL_TEST);
  glDisable(GL_CULL_FACE);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  glDepthFunc(GL_LEQUAL);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, targets->shadow_texture());

  draw_pass(list, Pass::Solid, states, frame_meshes, camera.eye);
  // The background after the solids: the depth test skips every pixel they cover.
  glDepthMask(GL_FALSE);
  if (style.background_gradient) draw_background();
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  glEnable(GL_BLEND);
  glEnable(GL_POLYGON_OFFSET_FILL);
  // Our own ground only where the environment has no floor (then the grid is drawn on that).
  const bool ground_in_scene = list.ground.environment_floor;
  const bool floor = style.floor && !ground_in_scene;
  if (floor || (style.grid && !ground_in_scene)) {
    glPolygonOffset(-1.0f, -1.0f);
    draw_ground_quad(focus, list.ground.z, floor);
  }
  glPolygonOffset(-2.0f, -4.0f);  // decals win against the surface they lie on
  glDepthMask(GL_TRUE);
  draw_pass(list, Pass::Decal, states, frame_meshes, camera.eye);
  glDisable(GL_POLYGON_OFFSET_FILL);
  glDepthMask(GL_FALSE);
  draw_pass(list, Pass::Translucent, states, frame_meshes, camera.eye);
  // X-ray: the hidden parts of forces and centres of mass, faded; back faces culled so that an
  // arrow does not show through itself.
  if (style.xray_opacity > 0.0f) {
    glDepthFunc(GL_GREATER);
    glEnable(GL_CULL_FACE);
    draw_pass(list, Pass::Xray, states, frame_meshes, camera.eye);
    glDisable(GL_CULL_FACE);
    glDepthFunc(GL_LEQUAL);
  }
  glDepthMask(GL_TRUE);
  glDisable(GL_BLEND);
  glDisable(GL_STENCIL_TEST);
  Image image = targets->read();
  if (style.samples <= 1 && style.edge_smoothing) smooth_edges(image);
  return image;
}

Renderer::Renderer(int width, int height, const RenderStyle& style,
                   std::shared_ptr<MeshLibrary> meshes)
    : impl_(std::make_unique<Impl>(width, height, style, std::move(meshes))) {}

Renderer::~Renderer() = default;

DrawList Renderer::assemble(const Scene& scene, const Eigen::VectorXd& q,
                            const std::vector<PlanContact>& contacts,
                            const std::vector<VertexForce>& forces) const {
  return assemble_frame(scene, q, contacts, forces, impl_->style, *impl_->meshes);
}

Camera Renderer::frame(const Scene& scene, const Eigen::VectorXd& q,
                       const std::vector<PlanContact>& contacts, View view) const {
  const DrawList list = assemble(scene, q, contacts, {});
  Eigen::AlignedBox3d box = list.bounds();
  if (box.isEmpty()) box = list.bounds(true);
  const double aspect = static_cast<double>(impl_->width) / impl_->height;
  return frame_box(box, view, aspect, frame_margins(impl_->style));
}

FrameMargins frame_margins(const RenderStyle& style) {
  FrameMargins margins;
  margins.side = 0.05;
  margins.top = style.caption ? 0.09 : 0.0;
  margins.bottom = style.legend ? 0.05 : 0.0;
  return margins;
}

Image Renderer::render(const DrawList& list, const Camera& camera) {
  return impl_->draw(list, camera);
}

Image Renderer::render(const Scene& scene, const Eigen::VectorXd& q,
                       const std::vector<PlanContact>& contacts,
                       const std::vector<VertexForce>& forces, const Camera& camera,
                       const std::string& caption) {
  Image image = impl_->draw(assemble(scene, q, contacts, forces), camera);
  const float px = text_px(impl_->height, impl_->style.text_scale);
  if (impl_->style.caption && !caption.empty()) draw_caption(image, caption, px);
  if (impl_->style.legend) draw_legend(image, impl_->style, 0.85f * px);
  return image;
}

int Renderer::width() const {
  return impl_->width;
}
int Renderer::height() const {
  return impl_->height;
}
const RenderStyle& Renderer::style() const {
  return impl_->style;
}

void Renderer::set_style(const RenderStyle& style) {
  const bool targets_change = style.samples != impl_->style.samples ||
                              style.shadows != impl_->style.shadows ||
                              style.shadow_map_size != impl_->style.shadow_map_size;
  impl_->style = style;
  if (targets_change) {
    impl_->context.make_current();
    impl_->targets.reset();
    impl_->create_targets();
  }
}

MeshLibrary& Renderer::meshes() const {
  return *impl_->meshes;
}
std::vector<std::string> Renderer::take_warnings() {
  return impl_->meshes->take_warnings();
}

std::string Renderer::gl_renderer() const {
  impl_->context.make_current();
  return impl_->context.renderer_name();
}

}  // namespace stanceplan::render
