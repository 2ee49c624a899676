#include "app/gui/node_details.h"

#include <algorithm>
#include <cmath>

namespace stanceplan::gui {
namespace {

std::vector<ContactRow> contact_rows(const Scene& scene, const SearchEvent& event) {
  std::vector<ContactRow> rows;
  for (const PlanContact& c : event.contacts) {
    ContactRow row;
    row.name =
        scene.surfaces.get(c.contact.s1).name + " on " + scene.surfaces.get(c.contact.s2).name;
    row.loaded = c.loaded;
    rows.push_back(row);
  }
  for (const VertexForce& f : event.forces) {
    if (f.contact < 0 || f.contact >= static_cast<int>(rows.size())) continue;
    rows[f.contact].force_W += f.force_W;
    ++rows[f.contact].vertices;
  }
  return rows;
}

// E19: each actuated dof against the effort limit of the joint that drives it.
std::vector<TorqueRow> torque_rows(const System& system, const SearchEvent& event) {
  std::vector<TorqueRow> rows;
  const int entities = std::min<int>(system.num_entities(), event.torques.size());
  for (int e = 0; e < entities; ++e) {
    const Entity& entity = system.entity(e);
    const Eigen::VectorXd& tau = event.torques[e];
    const int dofs = std::min<int>(tau.size(), entity.model->num_dofs());
    for (int k = 0; k < dofs; ++k) {
      const Joint& joint = entity.model->joints[entity.model->dof_joints[k]];
      rows.push_back({entity.name, joint.name, tau[k], joint.effort});
    }
  }
  return rows;
}

// q in the layout of planner/model/entity.h: [p_WB, quaternion_WB (w x y z)] for floating
// entities, then one entry per dof.
std::vector<ConfigurationRow> configuration_rows(const System& system, const Eigen::VectorXd& q) {
  static const char* const kBase[] = {"base x",  "base y",  "base z", "base qw",
                                      "base qx", "base qy", "base qz"};
  std::vector<ConfigurationRow> rows;
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    const int offset = system.offset(e);
    if (offset + entity.nq() > q.size()) break;
    for (int i = 0; i < entity.first_dof(); ++i)
      rows.push_back({entity.name, kBase[i], q[offset + i]});
    for (int k = 0; k < entity.model->num_dofs(); ++k)
      rows.push_back({entity.name, entity.model->joints[entity.model->dof_joints[k]].name,
                      q[offset + entity.first_dof() + k]});
  }
  return rows;
}

}  // namespace

NodeDetails node_details(const Scene& scene, const SearchEvent& event) {
  NodeDetails details;
  details.contacts = contact_rows(scene, event);
  for (const ContactRow& c : details.contacts) details.total_force_z += c.force_W.z();
  details.torques = torque_rows(scene.system, event);
  for (const TorqueRow& t : details.torques)
    details.worst_torque_ratio = std::max(details.worst_torque_ratio, t.ratio());
  for (const auto& [family, value] : event.residuals) details.residuals.push_back({family, value});
  details.configuration = configuration_rows(scene.system, event.q);
  std::stable_sort(details.residuals.begin(), details.residuals.end(),
                   [](const ResidualRow& a, const ResidualRow& b) { return a.value > b.value; });
  return details;
}

}  // namespace stanceplan::gui
