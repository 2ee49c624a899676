#pragma once
// The guide's milestone in the panel's 3-D view: the robots and objects at the milestone the
// search aims at, drawn as a translucent ghost over the event's own picture, so that a user sees
// where the search is heading (a computed guide's milestones state root positions only: the
// ghost's joints are the milestone's full configuration, its unstated entries completed as the
// search completes them). Render thread only (view_renderer.h).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "planner/scene/scene.h"
#include "render/renderer.h"

namespace stanceplan::gui {

// The milestone shown with an event: the one targeted after it (SearchEvent::milestone), or none
// when the scenario has no milestones. Its caption line: "aiming at milestone 3 of 10".
struct AimedMilestone {
  int index = -1;  // 0-based
  int count = 0;
  Eigen::VectorXd q;
};
std::optional<AimedMilestone> aimed_milestone(const std::vector<Eigen::VectorXd>& milestones,
                                              int targeted);
std::string aimed_caption(const AimedMilestone& m);

// Ghost colour: a light blue at 30 % opacity.
inline constexpr render::Color kGhostColor{0.45f, 0.65f, 1.0f, 0.3f};

// Renderer::render(scene, q, ...) with the robots and objects at `ghost_q` drawn translucent.
render::Image render_with_ghost(render::Renderer& renderer, const Scene& scene,
                                const Eigen::VectorXd& q, const std::vector<PlanContact>& contacts,
                                const std::vector<VertexForce>& forces,
                                const Eigen::VectorXd& ghost_q, const render::Camera& camera,
                                const std::string& caption);

}  // namespace stanceplan::gui
