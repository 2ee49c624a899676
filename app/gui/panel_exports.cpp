#include "app/gui/panel_exports.h"

#include <utility>

#include "app/pipeline.h"
#include "render/figures/sequence.h"
#include "render/image/png_io.h"

namespace stanceplan::gui {

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

ViewRenderer::Job export_strip_job(const Scenario& scenario, std::shared_ptr<const Plan> plan,
                                   std::shared_ptr<render::MeshLibrary> meshes, std::string path) {
  return [&scenario, plan = std::move(plan), meshes = std::move(meshes),
          path = std::move(path)](render::Renderer&) {
    const render::PlanView view = app::plan_view(scenario, *plan);
    render::write_png(path, render::render_strip(view, render::StripOptions{},
                                                 app::figure_options(view), meshes));
    return "saved " + path;
  };
}

}  // namespace stanceplan::gui
