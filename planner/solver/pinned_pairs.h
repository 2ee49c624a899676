#pragma once
// Collision pairs that a posture request leaves out of its program, and the check that keeps the
// ones left out for being constant honest.
//
// A pair is left out of the program (no E20 row) when
//  - its two links touch through a contact of the request (they are meant to touch), or
//  - both links are pinned: a link that never moves, or a moving link in a contact with a fixed
//    placement (E10-E13 fix all six relative degrees of freedom) with a link that never moves.
//    Their distance is a constant of the request: a row would only repeat the contact
//    equalities (rank-deficient), so none is written.
// A pinned pair's distance is still a fact of the posture: two feet placed into each other make
// every solution a collision. It is checked from the placements alone before any solve, and on
// the solution after it, against the same bound the program gives the pairs it does hold.
#include <Eigen/Geometry>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "planner/model/model_data.h"
#include "planner/scene/scene.h"
#include "planner/solver/posture_request.h"

namespace stanceplan {

enum class PairExclusion : unsigned char { None, Touching, Pinned };

// Per candidate pair of scene.collision (empty without one): why the request leaves it out.
std::vector<PairExclusion> pair_exclusions(const Scene& scene, const PostureRequest& request);

// The world pose that contact `task`'s fixed placement gives the link of `moving` (s1 or s2 of the
// contact), the other surface's link being at T_WL_other: E10-E13 read as a rigid transform
// (s1's origin at (x, y) in s2's plane, z1 = -z2, x1 at angle theta from x2).
Eigen::Isometry3d pinned_link_pose(const Scene& scene, const ContactTask& task, SurfaceRef moving,
                                   const Eigen::Isometry3d& T_WL_other);

// Overwrites, in `data` (forward kinematics of some configuration, one per entity), the world
// pose of every link the request pins with the pose its fixed placement gives it.
void place_pinned_links(const Scene& scene, const PostureRequest& request,
                        std::vector<ModelData>& data);

// Whether the request pins both links of some candidate pair (cheap: no kinematics, no distance).
bool has_pinned_pair(const Scene& scene, const PostureRequest& request);

// One pinned pair's signed distance at some poses.
struct PinnedPairDistance {
  int pair = -1;  // index into CollisionModel::pairs()
  double distance = 0.0;
  int contact_a = -1;  // the request contact pinning the pair's link a (-1: it never moves)
  int contact_b = -1;
};
std::vector<PinnedPairDistance> pinned_pair_distances(const Scene& scene,
                                                      const PostureRequest& request,
                                                      std::span<const ModelData> data);

// "robot/l_ankle" for collision link `l`.
std::string collision_link_name(const Scene& scene, int l);

}  // namespace stanceplan
