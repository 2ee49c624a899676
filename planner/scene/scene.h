#pragma once
// Everything the solver and the search need to know about the world, built once per scenario and
// shared read-only by every thread: the entities, their contact surfaces, their collision
// geometry and gravity.
#include <Eigen/Core>
#include <memory>

#include "planner/collision/collision_model.h"
#include "planner/contact/surface_set.h"
#include "planner/model/system.h"

namespace stanceplan {

struct Scene {
  System system;
  SurfaceSet surfaces;
  std::shared_ptr<const CollisionModel> collision;  // may be null: no collision avoidance
  Eigen::Vector3d gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
};

}  // namespace stanceplan
