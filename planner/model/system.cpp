#include "planner/model/system.h"

#include <algorithm>

#include "planner/util/input_error.h"

namespace stanceplan {

int System::add(Entity entity) {
  if (entity.name.empty()) throw InputError("entity: the name is empty");
  if (find_entity(entity.name) >= 0)
    throw InputError("entity \"" + entity.name + "\": the name is used twice");
  if (!entity.model) throw InputError("entity \"" + entity.name + "\": no model");
  if (entity.kind == EntityKind::Object && entity.model->num_dofs() != 0)
    throw InputError("entity \"" + entity.name + "\": an object is a rigid body, but model \"" +
                     entity.model->name + "\" has " + std::to_string(entity.model->num_dofs()) +
                     " movable joints (use kind \"floating\" for an articulated free body)");
  if (entity.kind == EntityKind::Environment && entity.model->num_dofs() != 0)
    throw InputError("entity \"" + entity.name +
                     "\": the environment must have no movable joint, "
                     "model \"" +
                     entity.model->name + "\" has " + std::to_string(entity.model->num_dofs()));
  offsets_.push_back(nq_);
  nq_ += entity.nq();
  entities_.push_back(std::move(entity));
  return num_entities() - 1;
}

int System::find_entity(const std::string& name) const {
  for (int i = 0; i < num_entities(); ++i)
    if (entities_[i].name == name) return i;
  return -1;
}

Eigen::VectorXd System::neutral_configuration() const {
  Eigen::VectorXd q = Eigen::VectorXd::Zero(nq_);
  for (int e = 0; e < num_entities(); ++e) {
    const Entity& entity = entities_[e];
    if (entity.floating()) q[offsets_[e] + Entity::kBaseQuaternion] = 1.0;  // w = 1
    const Model& model = *entity.model;
    for (int k = 0; k < model.num_dofs(); ++k) {
      const Joint& joint = model.joints[model.dof_joints[k]];
      double value = 0.0;
      if (joint.has_position_limits) value = std::clamp(value, joint.lower, joint.upper);
      q[offsets_[e] + entity.first_dof() + k] = value;
    }
  }
  return q;
}

}  // namespace stanceplan
