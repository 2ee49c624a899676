#pragma once
// The support-share ordering (SearchOptions::order_candidates; a heuristic: it orders, never
// prunes). With lazy expansion (SearchOptions::expansion_batch) the candidates of a node are solved
// a few at a time, best first, and the search moves on as soon as a child is better than the node:
// the order decides how many calls a step costs. A new contact is likely to carry its share of the
// load when the guide's posture (the node's posture carried to the targeted milestone,
// GuidePath::posture_near) already puts its surface on its partner, facing it: a sole above the
// tread the waist is guided over, not a knee on the floor while the guide stands, nor a palm on a
// tread 0.8 m below it.
#include <vector>

#include "planner/model/model_data.h"
#include "planner/scene/scene.h"
#include "planner/search/candidates.h"

namespace stanceplan {

// Weight of the normals' misalignment, in metres per unit of (1 + n1 . n2): 0 when they oppose
// (the contact's E8), 0.2 m when they are at right angles (a knee's normal and the floor's while
// standing), 0.4 m when they point the same way.
constexpr double kShareNormalWeight = 0.2;

// Weight of how far s1's centre is from s2's polygon (SurfaceGaps::centre) against the gap between
// the two polygons (SurfaceGaps::touching, 0 as soon as one corner touches): a sole whose back edge
// just reaches a platform's edge, its middle 0.12 m past it, is further from carrying its share
// than a palm under the sole's middle. Measured on the 23 untuned, paper and guide-free runs (`plan
// --threads 1`): 0.25 takes the guide-free climb from 22 calls and 13 steps (four of them shuffling
// on platform A, towards a milestone over the gap) to 19 calls and 9 steps, the paper's ball from
// 88 to 86, the other 21 unchanged; 0.1 changes nothing, 0.35 takes the guide-free stairs from 26
// to 28, 1 (the centre alone) to 37 and the untuned stairs from 24 to 30.
constexpr double kShareCentreWeight = 0.25;

// How far, in metres, the guide's posture is from realising contact c: the gap between its two
// surfaces there (surface_gaps, weighted) plus the normals' misalignment. `guide`
// holds forward kinematics at the guide's posture. Lower is more promising.
double support_share_score(const Scene& scene, const std::vector<ModelData>& guide,
                           const Contact& c);

// Additions that the guide's posture already realises (score at most `realised`, m; the search
// passes SearchOptions::placement_tolerance, negative: none is; the thighs
// just above the seat at a sitting milestone) first, then the removals in their given order (a
// step lifts a contact before it places one), then the other additions, each group by increasing
// support_share_score; ties keep the given order (deterministic). Returns the score of each
// candidate in the new order (0 for a removal). Why the first group: at the desk's crouch both
// feet are down and both thighs 2-7 mm above the seat; lifting a foot first sent the lazy search
// into single-support stances that cannot sit (147 calls instead of 91, README).
std::vector<double> order_by_support_share(const Scene& scene, const std::vector<ModelData>& guide,
                                           std::vector<Candidate>& candidates, double realised);

}  // namespace stanceplan
