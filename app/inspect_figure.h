#pragma once
// `stanceplan inspect MODEL --png FILE`: the model at its neutral configuration (root at the
// origin, joints at 0 clamped into their limits) with each of its contact surfaces drawn as a
// coloured patch named in the same colour (render/figures/surface_figure.h), written atomically.
#include <string>
#include <vector>

#include "planner/contact/surface.h"
#include "planner/model/entity.h"

namespace stanceplan::app {

struct SurfaceFigureRequest {
  std::shared_ptr<const Model> model;
  EntityKind kind = EntityKind::FixedRobot;
  std::vector<Surface> surfaces;
  std::string png;                     // output file
  std::string view = "three-quarter";  // front | side | top | three-quarter
  std::string caption;
};

// Throws InputError on an unknown view; std::runtime_error when no image can be made or written.
void write_surface_figure(const SurfaceFigureRequest& request);

}  // namespace stanceplan::app
