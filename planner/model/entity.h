#pragma once
// An entity of docs/METHOD.md section 1: a kinematic tree plus how its root is attached to the
// world. Configuration of one entity (the layout is defined here and nowhere else):
//   floating robot / object: [ p_WB (3) | quaternion_WB w,x,y,z (4) | dofs (n) ]
//   fixed robot / environment: [ dofs (n) ]                (root at the constant pose T_WB)
#include <Eigen/Geometry>
#include <memory>
#include <string>

#include "planner/model/model.h"

namespace stanceplan {

enum class EntityKind { Environment, FixedRobot, FloatingRobot, Object };

const char* to_string(EntityKind kind);
// Parses "environment" | "fixed" | "floating" | "object"; false when unknown.
bool parse_entity_kind(const std::string& text, EntityKind* kind);

struct Entity {
  std::string name;
  EntityKind kind = EntityKind::FixedRobot;
  std::shared_ptr<const Model> model;
  Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();  // root pose (fixed robot, environment)

  static constexpr int kBasePosition = 0;
  static constexpr int kBaseQuaternion = 3;
  static constexpr int kFloatingBaseSize = 7;

  bool floating() const { return kind == EntityKind::FloatingRobot || kind == EntityKind::Object; }
  // Index of the first joint dof in this entity's configuration segment.
  int first_dof() const { return floating() ? kFloatingBaseSize : 0; }
  int nq() const { return first_dof() + model->num_dofs(); }
};

}  // namespace stanceplan
