#pragma once
// The space the guide path is planned in (docs/METHOD.md section 3, "The guide computed"): the
// pose of every floating root (robot or object) that moves between the initial and the goal
// configuration, in SE(3), plus one phase s in [0, 1] that interpolates every joint (and the
// roots that do not move) between the two postures: the planner decides where along the way the
// joints move. A point of it is a vector x = [p (3), quaternion w, x, y, z (4)] per moving root,
// then s. Plain Eigen: the OMPL side (ompl_path.h) only copies numbers in and out.
#include <Eigen/Core>
#include <vector>

#include "planner/model/system.h"

namespace stanceplan {

class GuideSpace {
 public:
  // A root moves when its position changes by more than 1 mm or its orientation by 1 mrad.
  GuideSpace(const System& system, Eigen::VectorXd q_start, Eigen::VectorXd q_goal);

  int size() const { return 7 * int(moving_.size()) + 1; }
  const System& system() const { return system_; }
  const std::vector<int>& moving() const { return moving_; }  // entity indices
  const Eigen::VectorXd& q_start() const { return q_start_; }
  const Eigen::VectorXd& q_goal() const { return q_goal_; }
  Eigen::VectorXd x_start() const { return point_of(q_start_, 0.0); }
  Eigen::VectorXd x_goal() const { return point_of(q_goal_, 1.0); }

  // The point at t of the straight way from a to b: linear in positions and phase, spherical in
  // orientations.
  static Eigen::VectorXd between(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double t);
  // The configuration at x (allocates nothing when q already has System::nq() entries).
  void configuration(const Eigen::VectorXd& x, Eigen::VectorXd& q) const;
  // Base travel from a to b: the largest distance a moving root covers, its turn counted as
  // kTurnLength per radian (the search's GuideMetric weighs a radian as half a metre); the phase
  // when no root moves. Milestones are spaced by it.
  static constexpr double kTurnLength = 0.5;
  double travel(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const;
  // Whether entity e's orientation differs between the two postures by more than 0.1 rad (its
  // milestones then state it).
  bool turns(int e) const;

 private:
  Eigen::VectorXd point_of(const Eigen::VectorXd& q, double s) const;

  const System& system_;
  Eigen::VectorXd q_start_, q_goal_;
  std::vector<int> moving_;
};

}  // namespace stanceplan
