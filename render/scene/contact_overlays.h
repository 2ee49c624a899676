#pragma once
// The contact information of a frame as draw items: contact surfaces (loaded / unloaded), a force
// arrow per contact vertex scaled by magnitude, optional friction cones, each floating robot's
// centre of mass with its ground projection, and the support polygon of the contacts on the ground.
#include <vector>

#include "planner/plan/plan.h"
#include "planner/scene/scene.h"
#include "render/render_style.h"
#include "render/scene/draw_list.h"
#include "render/scene/scene_assembly.h"

namespace stanceplan::render {

// Metres per newton that the style asks for: its force_scale, or the automatic one drawing the
// largest of `forces` force_max_length long.
double force_scale(const RenderStyle& style, const std::vector<VertexForce>& forces);

// The ground projection and the support polygon lie on list.ground (set it first: ground.h).
void add_contact_overlays(const Scene& scene, const SystemPose& pose,
                          const std::vector<PlanContact>& contacts,
                          const std::vector<VertexForce>& forces, const RenderStyle& style,
                          DrawList& list);

// Convex hull (counter-clockwise) of 2-D points; fewer than 3 distinct points give what remains.
std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> points);

}  // namespace stanceplan::render
