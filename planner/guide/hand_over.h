#pragma once
// The hand-over of a carried object (docs/METHOD.md section 5, the dual-arm scenario; section 3,
// "The guide computed"): an object that moves from where one robot can hold it to where only
// another can must pass from hand to hand. Without it the guide's path carries the object
// straight over (the guide-free dual arm: no plan within 110 s, 1364 solver calls), nothing in it
// saying where one robot can hold it for the other.
//
// Carriers of an object: the robots with a surface the contact pairs let touch it. A carrier
// reaches a point when one of those surfaces can: the point lies within the stretched chain from
// the first moving joint above the surface's link (the sum of the joint offsets below it, a
// prismatic joint at its upper limit, plus the surface's farthest vertex; RBPRM's reachability
// condition, as the search's reach rule). That bound is necessary, not sufficient: a carrier
// within it at both ends carries the object alone only when one of its first grasps holds the
// object at each end, on the supports the initial and the goal stance give it (a posture solved,
// every contact loaded). When no carrier carries it from the initial to the goal position, a
// carrier that reaches the first hands it to one that reaches the second, at the point of the
// straight way between them that both reach with the most to spare; the hand-over posture is solved
// by the IK-statics program (section 4) with both carriers grasping the object, every grasp contact
// loaded: each grasp two of the carrier's surfaces on two opposed facets of the object (an
// antipodal grasp, E5: friction holds it), the facets whose normals lie across the carrier's way to
// the point first.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "planner/guide/guide_options.h"
#include "planner/plan/problem.h"

namespace stanceplan {

struct HandOver {
  int object = -1;         // entity index
  int from = -1, to = -1;  // the carriers (entity indices)
  Eigen::VectorXd q;       // the hand-over posture, both carriers grasping the object
  std::vector<StanceContact> grasps;
  int solves = 0;  // postures tried
};

// The hand-over `q_goal` (the goal posture) needs, nullopt when none does. `note` says why a
// needed one was not found ("" otherwise).
std::optional<HandOver> find_hand_over(const Problem& problem, const Eigen::VectorXd& q_goal,
                                       const GuideOptions& options, std::string* note);

}  // namespace stanceplan
