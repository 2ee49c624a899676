#pragma once
// The project's humanoid with a round fingertip on each hand (point surfaces l_tip and r_tip: a
// sphere of radius 0.02 m 0.15 m below the hand link's origin, past the palm), for the tests of
// point contacts.
#include <string>

#include "planner/contact/surface.h"
#include "tests/support/scenes.h"

namespace stanceplan::test {

inline Scene humanoid_scene_with_tips(const std::string& environment) {
  Scene scene = humanoid_scene(environment);
  const Model& model = *scene.system.entity(0).model;
  std::vector<Surface> surfaces = scene.surfaces.of(0);
  for (const std::string side : {"l", "r"}) {
    Surface tip;
    std::string error;
    make_point_surface(side + "_tip", model.find_link(side + "_hand"), side + "_hand",
                       Eigen::Vector3d(0.0, 0.0, -0.15), 0.02, &tip, &error);
    surfaces.push_back(tip);
  }
  scene.surfaces.set(0, std::move(surfaces));
  return scene;
}

}  // namespace stanceplan::test
