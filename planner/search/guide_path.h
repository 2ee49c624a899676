#pragma once
// The guide path of docs/METHOD.md section 3: milestone configurations q_ref,1..M and the distance
// the search's cost is measured in. A global milestone index t advances when the tree holds a
// configuration within tolerance of milestone t.
#include <Eigen/Core>
#include <vector>

#include "planner/model/system.h"

namespace stanceplan {

struct GuideMetric {
  double position = 1.0;     // weight of root positions (per metre)
  double orientation = 0.5;  // weight of root orientations (per radian of rotation angle)
  double joints = 0.1;       // weight of joint positions (per radian or metre)
};

class GuidePath {
 public:
  // masks[i] (optional): 1 for the entries milestone i states; distances to it ignore the others.
  GuidePath(const System& system, std::vector<Eigen::VectorXd> milestones,
            std::vector<Eigen::VectorXd> masks = {}, GuideMetric metric = {});

  int size() const { return static_cast<int>(milestones_.size()); }
  const Eigen::VectorXd& milestone(int t) const { return milestones_.at(t); }
  // Weighted distance from q to milestone t (root position, root rotation angle, joints) over the
  // entries the milestone states.
  double distance_to(const Eigen::VectorXd& q, int t) const;
  // q with every entry milestone t states taken from it: the guide's posture near q (a coarse
  // guide states base positions only: q's posture carried to the milestone's base).
  Eigen::VectorXd posture_near(const Eigen::VectorXd& q, int t) const;
  // Whether milestones t and u state the same entries.
  bool same_entries(int t, int u) const;

 private:
  const System& system_;
  // mask == nullptr: every entry.
  double distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                  const Eigen::VectorXd* mask) const;

  std::vector<Eigen::VectorXd> milestones_;
  std::vector<Eigen::VectorXd> masks_;
  GuideMetric metric_;
};

}  // namespace stanceplan
