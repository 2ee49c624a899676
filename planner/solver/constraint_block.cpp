#include "planner/solver/constraint_block.h"

#include <algorithm>

namespace stanceplan {

void append_link_columns(const System& system, int entity, int link, std::vector<int>* columns) {
  const Entity& e = system.entity(entity);
  const int offset = system.offset(entity);
  if (e.floating())
    for (int i = 0; i < Entity::kFloatingBaseSize; ++i) columns->push_back(offset + i);
  const Model& model = *e.model;
  for (int l = link; l > 0; l = model.links[l].parent_link) {
    const Joint& joint = model.joints[model.links[l].parent_joint];
    if (joint.movable()) columns->push_back(offset + e.first_dof() + joint.dof);
  }
}

void append_entity_columns(const System& system, int entity, std::vector<int>* columns) {
  const int offset = system.offset(entity);
  for (int i = 0; i < system.entity(entity).nq(); ++i) columns->push_back(offset + i);
}

void append_force_columns(const NlpLayout& layout, int task, std::vector<int>* columns) {
  const int b = layout.force_block_of_task[task];
  if (b < 0) return;
  const ForceBlock& block = layout.forces[b];
  for (int i = 0; i < block.size(); ++i) columns->push_back(block.first_column + i);
}

void append_loaded_contact_columns(const NlpState& state, int entity, std::vector<int>* columns) {
  for (int t = 0; t < static_cast<int>(state.constants.size()); ++t) {
    if (state.layout.force_block_of_task[t] < 0) continue;
    const ContactConstants& c = state.constants[t];
    if (c.e1 != entity && c.e2 != entity) continue;
    append_link_columns(state.scene.system, c.e1, c.l1, columns);
    append_link_columns(state.scene.system, c.e2, c.l2, columns);
    append_force_columns(state.layout, t, columns);
  }
}

void sort_unique(std::vector<int>* columns) {
  std::sort(columns->begin(), columns->end());
  columns->erase(std::unique(columns->begin(), columns->end()), columns->end());
}

}  // namespace stanceplan
