#pragma once
// Every contact surface of a scene as a draw item, for checking surfaces by eye (`stanceplan
// inspect MODEL --surfaces auto --png FILE`): each polygon filled in its own colour with a darker
// ring, lifted off its link along its outward normal, and where its label goes.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "planner/scene/scene.h"
#include "render/image/color.h"
#include "render/render_style.h"
#include "render/scene/camera.h"
#include "render/scene/draw_list.h"
#include "render/scene/scene_assembly.h"

namespace stanceplan::render {

// The i-th colour of a palette of well-separated hues (it repeats after twelve).
Color surface_color(int index);

struct SurfaceLabel {
  std::string text;     // "entity/surface"
  Eigen::Vector3d p_W;  // the polygon's centroid in the world, lifted like the patch
  Color color;
  bool point = false;  // a point surface: the name goes beside it, not over it
};

// Adds one translucent patch per surface of every entity (in SurfaceSet order, colour i for the
// i-th surface over all entities) and returns the labels in the same order.
std::vector<SurfaceLabel> add_surface_overlays(const Scene& scene, const SystemPose& pose,
                                               const RenderStyle& style, DrawList& list);

// Where a world point lands in an image of width x height seen by `camera` (pixels, y down);
// false when it lies behind the eye.
bool project_to_pixel(const Camera& camera, int width, int height, const Eigen::Vector3d& p_W,
                      Eigen::Vector2d& pixel);

}  // namespace stanceplan::render
