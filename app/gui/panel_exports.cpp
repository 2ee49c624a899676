#include "app/gui/panel_exports.h"

#include <utility>

#include "render/figures/sequence.h"
#include "render/image/png_io.h"

namespace stanceplan::gui {

LoadedPlan loaded_plan(const Scenario& scenario, const Plan& plan) {
  LoadedPlan loaded;
  loaded.scenario = scenario.file;
  loaded.spec = scenario.spec;
  loaded.scene = scenario.scene;
  loaded.friction = scenario.solver.friction;
  loaded.plan = plan;
  return loaded;
}

ViewRenderer::Job export_view_job(const Scene& scene, ViewRequest view,
                                  std::shared_ptr<render::MeshLibrary> meshes, std::string path) {
  return [&scene, view = std::move(view), meshes = std::move(meshes),
          path = std::move(path)](render::Renderer&) {
    // The default style is the PNG figures' (multisampling, fine shadow map); the live view uses
    // the cheaper preview style.
    render::Renderer figure(view.width, view.height, render::RenderStyle{}, meshes);
    render::write_png(
        path, figure.render(scene, view.q, view.contacts, view.forces, view.camera, view.caption));
    return "saved " + path;
  };
}

ViewRenderer::Job export_strip_job(std::shared_ptr<const LoadedPlan> plan,
                                   std::shared_ptr<render::MeshLibrary> meshes, std::string path) {
  return [plan = std::move(plan), meshes = std::move(meshes),
          path = std::move(path)](render::Renderer&) {
    render::SequenceOptions options;
    options.style.friction = plan->friction;
    render::write_png(path, render::render_strip(*plan, render::StripOptions{}, options, meshes));
    return "saved " + path;
  };
}

}  // namespace stanceplan::gui
