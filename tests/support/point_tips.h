#pragma once
// The project's humanoid with a round fingertip on each hand (point surfaces l_tip and r_tip: a
// sphere of radius 0.02 m 0.15 m below the hand link's origin, past the palm), for the tests of
// point contacts.
#include <string>

#include "planner/contact/surface.h"
#include "planner/io/scenario.h"
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

// The initial stance of `scenario` with each s1 replaced by a point surface of `radius` at
// that surface's origin, added to its entity (hand_ball_rotate.yaml: fingertips holding the ball,
// an object whose surfaces turn with it). Every contact loaded, free placements.
inline PostureRequest with_point_tips(Scenario& scenario, double radius = 0.008) {
  Scene& s = scenario.scene;
  PostureRequest request;
  for (const StanceContact& sc : scenario.initial_stance) {
    const SurfaceRef pad = sc.contact.s1;
    const Surface& pad_surface = s.surfaces.get(pad);
    Surface tip;
    std::string error;
    make_point_surface(pad_surface.name + "_point", pad_surface.link, pad_surface.link_name,
                       pad_surface.T_LS.translation(), radius, &tip, &error);
    std::vector<Surface> surfaces = s.surfaces.of(pad.entity);
    surfaces.push_back(tip);
    s.surfaces.set(pad.entity, surfaces);
    ContactTask task;
    task.contact.s1 = {pad.entity, int(surfaces.size()) - 1};
    task.contact.s2 = sc.contact.s2;
    request.contacts.push_back(task);
  }
  request.q_init = scenario.initial_configuration;
  return request;
}

}  // namespace stanceplan::test
