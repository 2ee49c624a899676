#include "app/gui/guide_overlay.h"

#include <algorithm>

#include "render/figures/annotations.h"

namespace stanceplan::gui {

std::optional<AimedMilestone> aimed_milestone(const std::vector<Eigen::VectorXd>& milestones,
                                              int targeted) {
  if (milestones.empty()) return std::nullopt;
  const int index = std::clamp(targeted, 0, int(milestones.size()) - 1);
  return AimedMilestone{index, int(milestones.size()), milestones[size_t(index)]};
}

std::string aimed_caption(const AimedMilestone& m) {
  return "aiming at milestone " + std::to_string(m.index + 1) + " of " + std::to_string(m.count) +
         " (translucent)";
}

render::Image render_with_ghost(render::Renderer& renderer, const Scene& scene,
                                const Eigen::VectorXd& q, const std::vector<PlanContact>& contacts,
                                const std::vector<VertexForce>& forces,
                                const Eigen::VectorXd& ghost_q, const render::Camera& camera,
                                const std::string& caption) {
  render::DrawList list = renderer.assemble(scene, q, contacts, forces);
  render::DrawList ghost = renderer.assemble(scene, ghost_q, {}, {});
  // The ghost's links only: no environment (drawn once already), no overlays (centre of mass,
  // support polygon: those of the event's own configuration are the ones that mean something).
  for (const render::DrawItem& item : ghost.items) {
    if (item.environment || item.transient || item.layer != render::Layer::Solid) continue;
    render::DrawItem g = item;
    g.layer = render::Layer::Translucent;
    g.color = kGhostColor;
    g.vertex_colors = false;
    g.casts_shadow = false;
    g.frames_view = false;
    g.xray = false;
    list.items.push_back(g);
  }
  render::Image image = renderer.render(list, camera);
  const render::RenderStyle& style = renderer.style();
  const float px = render::text_px(renderer.height(), style.text_scale);
  if (style.caption && !caption.empty()) render::draw_caption(image, caption, px);
  if (style.legend) render::draw_legend(image, style, 0.85f * px);
  return image;
}

}  // namespace stanceplan::gui
