#include "planner/model/model.h"

#include <stdexcept>

namespace stanceplan {

int Model::find_link(const std::string& link_name) const {
  for (int i = 0; i < num_links(); ++i)
    if (links[i].name == link_name) return i;
  return -1;
}

int Model::find_joint(const std::string& joint_name) const {
  for (int i = 0; i < static_cast<int>(joints.size()); ++i)
    if (joints[i].name == joint_name) return i;
  return -1;
}

int Model::find_dof(const std::string& joint_name) const {
  for (int k = 0; k < num_dofs(); ++k)
    if (joints[dof_joints[k]].name == joint_name) return k;
  return -1;
}

bool Model::adjacent(int link_a, int link_b) const {
  return links[link_a].parent_link == link_b || links[link_b].parent_link == link_a;
}

void Model::finalize() {
  if (links.empty()) throw std::logic_error("model \"" + name + "\" has no link");
  if (links[0].parent_link != -1) throw std::logic_error("model root has a parent");
  total_mass = 0.0;
  for (int i = 0; i < num_links(); ++i) {
    const Link& link = links[i];
    total_mass += link.inertial.mass;
    if (i == 0) continue;
    if (link.parent_link < 0 || link.parent_link >= i)
      throw std::logic_error("link \"" + link.name + "\" is not in topological order");
    const Joint& joint = joints.at(link.parent_joint);
    if (joint.child_link != i || joint.parent_link != link.parent_link)
      throw std::logic_error("joint \"" + joint.name + "\" does not match its child link");
  }
  subtree_mass.assign(links.size(), 0.0);
  for (int i = num_links() - 1; i >= 0; --i) {
    subtree_mass[i] += links[i].inertial.mass;
    if (i > 0) subtree_mass[links[i].parent_link] += subtree_mass[i];
  }
  for (int k = 0; k < num_dofs(); ++k) {
    const Joint& joint = joints.at(dof_joints[k]);
    if (joint.dof != k || joint.is_mimic || !joint.movable())
      throw std::logic_error("dof " + std::to_string(k) + " is inconsistent");
  }
  for (const Joint& joint : joints)
    if (joint.movable() && (joint.dof < 0 || joint.dof >= num_dofs()))
      throw std::logic_error("joint \"" + joint.name + "\" drives no dof");
}

}  // namespace stanceplan
