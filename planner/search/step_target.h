#pragma once
// Where a case-1 step aims (obj4, docs/METHOD.md E25): s1's placement in the targeted milestone,
// pulled back along the step when it would land on another contact. A side-step shows why: once the
// milestone advances while the robot stands on its leading foot, the trailing foot's placement in
// the next milestone lies under the leading foot, and the solve can only cycle at the foot-foot
// collision boundary until its iteration limit.
#include <vector>

#include "planner/contact/contact.h"
#include "planner/scene/scene.h"

namespace stanceplan {

// A step whose path puts s1's origin on the footprint of another contact on the same surface
// crosses it (the trailing foot of a side-step aimed past the leading one); it then stops where
// the footprint still keeps kStepTargetClearance (m) from the other contacts, short of the
// collision boundary where the solve would cycle. (A target that merely overlaps another
// footprint, e.g. the toes of a yawed foot beside the other foot in a forward step, is left to
// the solver: pulling it back shortens ordinary steps.)
inline constexpr double kStepTargetClearance = 0.02;

// s1's polygon on s2's plane, in s2's frame, with s1 at `placement` (s1's normal opposes s2's);
// a point surface's is the square of half-side r (at least 1 mm) around its contact point.
std::vector<Eigen::Vector2d> footprint_S2(const Surface& s1, const Placement& placement);

// Separation of two convex polygons along the best separating axis (SAT): > 0 apart (a lower bound
// of their distance), <= 0 overlapping.
double footprint_separation(const std::vector<Eigen::Vector2d>& a,
                            const std::vector<Eigen::Vector2d>& b);

// Whether the point p (s2's frame) lies inside the convex footprint (counter-clockwise).
bool footprint_contains(const std::vector<Eigen::Vector2d>& footprint, const Eigen::Vector2d& p);

// The target of adding `added` to `stance` (contacts at `placements`): the point at `share` of the
// way from `now` (s1's placement at the node) to `aim` (in the milestone), unless that way crosses
// a contact of the stance on the same s2; then the farthest point before the crossing that keeps
// kStepTargetClearance (or, when `now` is already closer, the gap at `now`). The orientation is
// the aim's.
Placement step_target(const Scene& scene, const Stance& stance,
                      const std::vector<Placement>& placements, const Contact& added,
                      const Placement& now, const Placement& aim, double share);

// Where a solve aimed at `target` can put s1 with its footprint inside s2's polygon (case 1's
// relaxed E10-E11): `target` when the footprint fits there, else the last point of the way from
// `now` where it fits (the sole aimed past a platform's edge stops at the edge), found by
// bisection (along a line, the points where a convex footprint fits in a convex polygon form one
// interval). `target` itself when the footprint does not fit at `now` either. An estimate for
// ordering candidates: the solver's placement also depends on the rest of the body.
Placement landing_estimate(const Scene& scene, const Contact& added, const Placement& now,
                           const Placement& target);

}  // namespace stanceplan
