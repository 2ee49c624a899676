#include "app/inspect_figure.h"

#include "planner/scene/scene.h"
#include "planner/util/input_error.h"
#include "render/figures/surface_figure.h"
#include "render/image/png_io.h"
#include "render/renderer.h"

namespace stanceplan::app {
namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 720;

// One entity, no collision model: nothing here checks distances.
Scene single_entity_scene(const SurfaceFigureRequest& request) {
  Scene scene;
  Entity entity;
  entity.name = request.model->name;
  entity.kind = request.kind;
  entity.model = request.model;
  scene.system.add(entity);
  scene.surfaces = SurfaceSet(1);
  scene.surfaces.set(0, request.surfaces);
  return scene;
}

}  // namespace

void write_surface_figure(const SurfaceFigureRequest& request) {
  const auto view = render::parse_view(request.view);
  if (!view)
    throw InputError("--view: expected front, side, top or three-quarter, found \"" + request.view +
                     "\"");
  const Scene scene = single_entity_scene(request);
  render::RenderStyle style;
  style.legend = false;
  style.center_of_mass = false;  // a model alone: no stance, nothing to balance
  render::Renderer renderer(kWidth, kHeight, style);
  const render::Image image = render::render_surface_figure(
      renderer, scene, scene.system.neutral_configuration(), *view, request.caption);
  render::write_png(request.png, image);
}

}  // namespace stanceplan::app
