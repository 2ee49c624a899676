#pragma once
// Scenes built from the project's assets, for solver and search tests.
#include <string>

#include "planner/scene/scene_builder.h"
#include "planner/solver/posture_request.h"
#include "tests/support/paths.h"

namespace stanceplan::test {

inline EntitySpec humanoid_spec() {
  EntitySpec e;
  e.name = "robot";
  e.kind = EntityKind::FloatingRobot;
  e.urdf = source_path("assets/robots/humanoid/humanoid.urdf");
  e.surfaces = source_path("assets/robots/humanoid/humanoid.surfaces.yaml");
  return e;
}

inline EntitySpec environment_spec(const std::string& name) {
  EntitySpec e;
  e.name = "env";
  e.kind = EntityKind::Environment;
  e.urdf = source_path("assets/environments/" + name + "/" + name + ".urdf");
  e.surfaces = source_path("assets/environments/" + name + "/" + name + ".surfaces.yaml");
  return e;
}

// The humanoid and one of the environments of assets/environments.
inline Scene humanoid_scene(const std::string& environment) {
  SceneSpec spec;
  spec.entities = {humanoid_spec(), environment_spec(environment)};
  return build_scene(spec);
}

inline SurfaceRef surface(const Scene& scene, const std::string& id) {
  return *scene.surfaces.find(scene.system, id);
}

inline ContactTask task(const Scene& scene, const std::string& s1, const std::string& s2,
                        bool loaded = true) {
  ContactTask t;
  t.contact.s1 = surface(scene, s1);
  t.contact.s2 = surface(scene, s2);
  t.loaded = loaded;
  return t;
}

// The humanoid standing straight with its soles on z = 0 (waist height 0.93 m).
inline Eigen::VectorXd standing_configuration(const Scene& scene) {
  Eigen::VectorXd q = scene.system.neutral_configuration();
  q[2] = 0.93;
  return q;
}

}  // namespace stanceplan::test
