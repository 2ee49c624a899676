#pragma once
// A figure for checking contact surfaces by eye: the scene at a configuration, every surface a
// coloured patch (render/scene/surface_overlays.h) with its name beside it in the same colour, and
// a caption. What `stanceplan inspect MODEL --surfaces ... --png FILE` writes.
#include <Eigen/Core>
#include <string>

#include "planner/scene/scene.h"
#include "render/image/image.h"
#include "render/renderer.h"
#include "render/scene/camera.h"

namespace stanceplan::render {

// Framed on the surfaces and the robots (the whole scene when it has neither) from `view`.
Image render_surface_figure(Renderer& renderer, const Scene& scene, const Eigen::VectorXd& q,
                            View view, const std::string& caption);

}  // namespace stanceplan::render
