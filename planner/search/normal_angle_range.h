#pragma once
// The angles two link-fixed directions of one model can make, over the joint limits: the test
// behind the candidate rule "two planar contacts of one robot whose surface normals cannot make
// the angle their partners' normals make" (candidates.h). A planar contact turns s1's normal
// against s2's (E8), so two contacts of links A and B of one robot with surfaces of one rigid body
// (the floor and a tread, both static) force the angle between A's and B's surface normals to the
// angle between the partners' normals: a knee flat on the floor while the sole of the same leg is
// flat on it needs an ankle pitch of 90 degrees. RBPRM (Tonneau et al., T-RO 2018) tests reach
// before any whole-body solve; this is the same idea for orientation, and exact (no heuristic).
#include <Eigen/Core>

#include "planner/model/model.h"
#include "planner/scene/scene.h"
#include "planner/search/surface_pair_cache.h"

namespace stanceplan {

struct AngleRange {
  double lo = 0.0;   // rad, a lower bound of every angle the directions can make
  double hi = M_PI;  // rad, an upper bound
  bool contains(double angle, double tolerance) const {
    return angle >= lo - tolerance && angle <= hi + tolerance;
  }
};

// Bounds of the angle between u_a (unit, link_a's frame) and u_b (unit, link_b's frame) over every
// configuration within the joint limits. The rotations on the tree path between the two links
// depend on the dofs of its revolute and continuous joints (mimic joints through their source);
// with at most kMaxGridDofs such dofs, the angle is evaluated on a grid over their box and the
// grid's extremes widened by its Lipschitz margin (turning a joint by d turns any direction by at
// most d, so the angle moves by at most sum |multiplier| * half the grid spacing per dof): sound.
// With more dofs the bounds are [0, pi] (nothing pruned).
constexpr int kMaxGridDofs = 4;
constexpr int kGridPoints = 20000;  // evaluations per pair at most
AngleRange normal_angle_range(const Model& model, int link_a, const Eigen::Vector3d& u_a,
                              int link_b, const Eigen::Vector3d& u_b);

// normal_angle_range of two surfaces' normals, computed on first use and kept. One per search:
// not thread-safe.
class NormalAngleTable {
 public:
  explicit NormalAngleTable(const Scene& scene) : scene_(scene) {}
  // a and b on one entity.
  const AngleRange& between(SurfaceRef a, SurfaceRef b);

 private:
  const Scene& scene_;
  SurfacePairCache<AngleRange> ranges_;
};

}  // namespace stanceplan
