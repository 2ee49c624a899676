#pragma once
// What the panel saves, as jobs for the render thread (view_renderer.h): the current view at
// figure quality and the plan's strip, both PNG (written atomically by render::write_png).
#include <memory>
#include <string>

#include "app/gui/view_renderer.h"
#include "planner/io/scenario.h"
#include "planner/plan/plan.h"

namespace stanceplan::gui {

// Renders `view` again in the default (figure) style at the same size and camera, writes `path`
// and returns "saved PATH".
ViewRenderer::Job export_view_job(const Scene& scene, ViewRequest view,
                                  std::shared_ptr<render::MeshLibrary> meshes, std::string path);
// Renders the plan's figure strip (render_strip with its default layout) into `path`; the
// scenario outlives the render thread.
ViewRenderer::Job export_strip_job(const Scenario& scenario, std::shared_ptr<const Plan> plan,
                                   std::shared_ptr<render::MeshLibrary> meshes, std::string path);

}  // namespace stanceplan::gui
