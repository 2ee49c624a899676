#pragma once
// Several entities planned together (docs/METHOD.md section 1): q = (q_1, ..., q_N), each entity's
// segment laid out as Entity documents, segments concatenated in the order entities were added.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "planner/model/entity.h"

namespace stanceplan {

class System {
 public:
  // Returns the entity's index. Throws InputError on a duplicate or empty name, or a floating
  // kind on a model whose root would need limits it cannot have (objects must be one-link trees).
  int add(Entity entity);

  const std::vector<Entity>& entities() const { return entities_; }
  const Entity& entity(int index) const { return entities_[index]; }
  int num_entities() const { return static_cast<int>(entities_.size()); }
  int find_entity(const std::string& name) const;  // -1 when absent
  int nq() const { return nq_; }
  int offset(int entity_index) const { return offsets_[entity_index]; }

  // Identity base orientation at the origin, every joint at 0 clamped into its limits.
  Eigen::VectorXd neutral_configuration() const;

 private:
  std::vector<Entity> entities_;
  std::vector<int> offsets_;
  int nq_ = 0;
};

}  // namespace stanceplan
