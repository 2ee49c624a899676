#pragma once
// How far apart two surfaces of one robot can ever be: the test behind the candidate rule "a new
// contact whose surface lies beyond the reach of a contact the stance keeps" (candidates.h). This
// is RBPRM's reachability condition (Tonneau et al., T-RO 2018: a limb's contact must lie within
// the workspace of its chain from the fixed part of the robot), made sound and computed once from
// the model: the bound holds at every configuration, whatever the joint limits and the collision
// model allow, so a candidate beyond it can never be realised.

#include "planner/model/model.h"
#include "planner/scene/scene.h"
#include "planner/search/surface_pair_cache.h"

namespace stanceplan {

// An upper bound of |p_W(a) - p_W(b)| over every configuration, for the frame origins of two
// links of one model. A revolute or continuous joint turns its child about an axis through the
// joint frame's origin, which is the child link's origin: the distance from a link's origin to its
// parent's is |p_PJ| at every angle. A prismatic joint adds at most the largest |value| its limits
// allow. The bound is the sum of these lengths along the tree path between the two links (the
// triangle inequality). INFINITY when a prismatic joint on the path has no limits.
double link_origin_reach(const Model& model, int link_a, int link_b);

// An upper bound of the distance between any point of surface a and any point of surface b (one
// entity) over every configuration: link_origin_reach plus each polygon's farthest vertex from its
// link's origin (plus the radius of a point surface: its contact point lies r from its centre).
// Computed on first use and kept: one table per search, not thread-safe.
class ReachTable {
 public:
  explicit ReachTable(const Scene& scene) : scene_(scene) {}
  double between(SurfaceRef a, SurfaceRef b);

 private:
  const Scene& scene_;
  SurfacePairCache<double> reach_;
};

}  // namespace stanceplan
