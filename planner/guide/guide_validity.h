#pragma once
// Which configurations the computed guide path may pass through (docs/METHOD.md section 3, "The
// guide computed"): the paper keeps its guide in C_free close to the obstacles that can serve as
// supports; this is that trade-off as a simple rule, in the spirit of RBPRM's reachability
// condition (the trunk clear of obstacles, a support within reach of a limb):
//  - the trunk collision-free with a clearance: every candidate collision pair of the scene keeps
//    GuideOptions::clearance, except
//    - a floating robot's links that carry a surface of a contact of the initial or goal stance
//      (the task's supporting limbs: soles, thighs, forearms) with the links of other entities
//      carrying a surface they may touch (the contact pairs): not checked, as RBPRM checks only
//      the trunk and lets the limbs find their contacts (without this the feet, interpolated
//      rigidly, cannot pass a stair's riser). Only those links: with every robot surface offered
//      every surface of a room (contact pairs [robot/*, env/*]), exempting every link that
//      carries a surface let the shanks pass through a chair's seat and the guide lead the robot
//      across the chair, where no step can follow;
//    - a fixed robot's moving links (arm, fingers; not its base or palm) with an object it may
//      touch (a carrier: its arm moves with the object, the guide plans the object's way, not
//      the arm's);
//    - the other links of a contact of the initial or goal stance (an object on a platform, a
//      fingertip on a ball, a palm on a handle): they may touch, but sink into each other by at
//      most kTouchDepth more than at either end;
//    - the pairs closer than the clearance at the initial or at the goal configuration (the task
//      starts or ends there: a thigh on a chair's seat beside its contact): not checked;
//    - self-collision pairs: not checked. The guide's joints are a straight line between two
//      postures that the search's postures replace (each solve keeps the robot off itself); a
//      hand's fingertips, interpolated, pass each other where no real motion would.
//  - a support within reach: a floating robot under gravity has a contact-capable surface (one
//    that the contact pairs offer, or one of a contact of the initial or goal stance) whose origin
//    lies within GuideOptions::reach of a surface of another entity it may touch (objects,
//    carried, need none).
// Const model (pairs, supports) plus one workspace: valid() allocates nothing.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "planner/collision/collision_model.h"
#include "planner/guide/guide_options.h"
#include "planner/model/model_data.h"
#include "planner/plan/problem.h"

namespace stanceplan {

// Whether the contact pairs (search.contact_pairs patterns; empty: every pair) offer a contact
// between surfaces a and b, in either order.
bool offered(const Scene& scene, SurfaceRef a, SurfaceRef b,
             const std::vector<std::pair<std::string, std::string>>& patterns);

// How deep the links of a stance's contact may sink into each other along the guide (m).
inline constexpr double kTouchDepth = 0.005;

class GuideValidity {
 public:
  GuideValidity(const Problem& problem, const Eigen::VectorXd& q_start,
                const Eigen::VectorXd& q_goal, const GuideOptions& options);

  bool valid(const Eigen::VectorXd& q);
  // Why q is not valid, for messages ("robot/l_knee - env/chair 0.004 m < clearance 0.01 m",
  // "robot: no contact-capable surface within 0.45 m of a support"); "" when valid.
  std::string why_invalid(const Eigen::VectorXd& q);

  int num_checked_pairs() const { return int(checked_pairs_.size()); }

 private:
  struct Support {  // a contact-capable surface of a floating robot and one it may touch
    int robot = -1;
    SurfaceRef own, other;
  };
  void update(const Eigen::VectorXd& q);
  int first_colliding_pair(double* distance);  // index into checked_pairs_, -1 when none
  int first_unsupported_robot() const;         // entity index, -1 when none
  double support_distance(const Support& s) const;

  const Problem& problem_;
  GuideOptions options_;
  // (index into the scene's CollisionModel::pairs(), the least distance it keeps)
  std::vector<std::pair<int, double>> checked_pairs_;
  std::vector<Support> supports_;  // grouped by robot
  std::vector<int> robots_;        // floating robots that need a support
  std::vector<ModelData> data_;
  std::vector<CollisionData> collision_data_;  // one, when the scene has a collision model
};

}  // namespace stanceplan
