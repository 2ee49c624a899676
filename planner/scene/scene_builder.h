#pragma once
// Builds a Scene from entity descriptions (URDF, surface file, SRDF, kind, base pose): what a
// scenario file's `entities` section says. File faults throw InputError naming the file.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "planner/contact/affordances.h"
#include "planner/scene/scene.h"

namespace stanceplan {

struct EntitySpec {
  std::string name;
  EntityKind kind = EntityKind::FixedRobot;
  std::string urdf;
  std::string surfaces;  // optional
  // `surfaces: auto`: surfaces extracted from the collision geometry instead of a file
  // (planner/contact/affordances.h); environments only.
  std::optional<AffordanceOptions> auto_surfaces;
  std::string srdf;  // optional: disabled collision pairs
  std::vector<std::string> package_paths;
  Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();  // fixed robots and environment
};

struct SceneSpec {
  std::vector<EntitySpec> entities;
  // Extra pairs never checked for collision, as ("entity/link", "entity/link").
  std::vector<std::pair<LinkName, LinkName>> ignored_pairs;
  Eigen::Vector3d gravity = Eigen::Vector3d(0.0, 0.0, -9.81);
  bool collision = true;
  // Robots whose SRDF disables none of their pairs, or which have none, get a self-collision matrix
  // computed with these options (CollisionOptions::computed_matrix); nullopt: none is computed.
  std::optional<CollisionMatrixOptions> collision_matrix = CollisionMatrixOptions{};
};

Scene build_scene(const SceneSpec& spec, HullCache* cache = nullptr);

}  // namespace stanceplan
