#pragma once
// Adj+ and Adj- of a stance (docs/METHOD.md section 2): the candidate contacts to add (one per
// class of equivalent stances: a pair of surfaces, the solver picks the placement) and to remove,
// after the pruning rules below. Each rule either cannot remove a feasible transition, or is a
// documented option of SearchOptions:
//  - same link: a contact needs two links (exact);
//  - both surfaces on bodies that never move (the environment, a fixed robot's base): their
//    relative placement is constant, so the contact is either always or never there (exact);
//  - a surface already in the stance as s1, or s2 already the s1 of a contact (stance rule);
//  - two contacts between the same two rigid bodies whose surface normals make different angles
//    on the two bodies (a planar contact turns s1's normal against s2's, so the angles must agree;
//    exact): a side of a standing cylinder on the platform it stands on, or on the floor;
//  - the same for two links of one robot joined by joints, when the joint limits between them
//    cannot give their normals the angle the partners' normals make (normal_angle_range.h;
//    exact): a knee flat on the floor while the same leg's sole is flat on the floor or a tread;
//  - a new contact whose surface x must touch a partner that never moves (the floor, a tread, the
//    desk) farther from a kept contact's surface y than any posture can put x from y, when that
//    kept contact's partner never moves either (reach_bound.h: RBPRM's reachability condition,
//    with the sum of the link lengths between x's and y's links; exact): the humanoid's free sole
//    on a tread 2.85 m from the sole it stands on (two stretched legs reach 2.10 m). It cannot
//    prune a contact with a moving partner (an object, another robot, the robot itself), nor
//    through a chain of contacts (a hand that the other hand could bring closer by moving the body
//    it holds), and the bound, being the stretched chain's, is loose for bent limbs: it prunes
//    what no posture reaches, not what no balanced posture does;
//  - removing the last contact that supports a floating body with mass: no equilibrium is
//    possible without support (exact), and fixed contacts are never removed (docs/METHOD.md);
//  - removing a contact that leaves such a body fewer than SearchOptions::min_contacts (option);
//  - two surfaces of one entity unless SearchOptions::self_contacts (option);
//  - surfaces farther apart than SearchOptions::contact_reach at the node's configuration: one
//    transition moves a link by a bounded amount (option);
//  - pairs not matching SearchOptions::contact_pairs, when the scenario lists them (option);
//  - pairs matching SearchOptions::last_contacts before every other goal contact is in the
//    stance (option).
// Besides these, the search (search_requests.cpp) defers to backtracking, never prunes: removals
// whose child is a node already (exact, skipped), additions aimed at a node's placement
// (defer_predicted_loops), removals that leave a held object unbalanced (object_balance.h,
// defer_unbalanced_removals) and candidates that failed from the same situation
// (failure_memo.h, defer_repeated_failures).
#include <vector>

#include "planner/contact/contact.h"
#include "planner/model/model_data.h"
#include "planner/scene/scene.h"
#include "planner/search/normal_angle_range.h"
#include "planner/search/reach_bound.h"
#include "planner/search/search_options.h"

namespace stanceplan {

struct Candidate {
  bool add = true;  // case 1 (add `contact`) or case 2 (remove `contact`)
  Contact contact;
};

// `data` holds forward kinematics of every entity at the node's configuration. `goal` supplies the
// orientation (which surface is s1) and the bilateral/fixed tags of contacts it contains.
// `angles` and `reach` (kept by the caller across calls) enable the normal-angle and the reach
// rules; null skips them.
std::vector<Candidate> enumerate_candidates(const Scene& scene, const std::vector<ModelData>& data,
                                            const Stance& stance, const Stance& goal,
                                            const SearchOptions& options,
                                            NormalAngleTable* angles = nullptr,
                                            ReachTable* reach = nullptr);

// Distance between two surfaces' polygons in the world (0 when they touch or cross).
double surface_gap(const Scene& scene, const std::vector<ModelData>& data, SurfaceRef a,
                   SurfaceRef b);

// Two measures of how far surface a is from surface b, from one pass over their world polygons:
// `touching`, surface_gap's; `centre`, from the centre of a's polygon (the mean of its vertices)
// to b's polygon: how far a is from lying on b, not only from touching it. A sphere (either
// surface a point): both are surface_gap.
struct SurfaceGaps {
  double touching = 0.0;
  double centre = 0.0;
};
SurfaceGaps surface_gaps(const Scene& scene, const std::vector<ModelData>& data, SurfaceRef a,
                         SurfaceRef b);

// True when a link's pose never depends on the configuration.
bool link_is_static(const Scene& scene, int entity, int link);

}  // namespace stanceplan
