#pragma once
// What the panel saves, as jobs for the render thread (view_renderer.h): the current view at
// figure quality and the plan's strip, both PNG (written atomically by render::write_png).
#include <memory>
#include <string>

#include "app/gui/view_renderer.h"
#include "planner/io/plan_reader.h"
#include "planner/io/scenario.h"

namespace stanceplan::gui {

// The plan found by the search, with the scenario's scene, as the plan reader would give it back
// (what render::render_strip and render::step_caption take).
LoadedPlan loaded_plan(const Scenario& scenario, const Plan& plan);

// Renders `view` again in the default (figure) style at the same size and camera, writes `path`
// and returns "saved PATH".
ViewRenderer::Job export_view_job(const Scene& scene, ViewRequest view,
                                  std::shared_ptr<render::MeshLibrary> meshes, std::string path);
// Renders the plan's figure strip (render_strip with its default layout) into `path`.
ViewRenderer::Job export_strip_job(std::shared_ptr<const LoadedPlan> plan,
                                   std::shared_ptr<render::MeshLibrary> meshes, std::string path);

}  // namespace stanceplan::gui
