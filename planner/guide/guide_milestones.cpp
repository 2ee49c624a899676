#include "planner/guide/guide_milestones.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace stanceplan {
std::vector<Eigen::VectorXd> points_along(const GuideSpace& space,
                                          const std::vector<Eigen::VectorXd>& waypoints,
                                          double spacing) {
  std::vector<double> at{0.0};  // travel at each waypoint
  for (size_t i = 1; i < waypoints.size(); ++i)
    at.push_back(at.back() + space.travel(waypoints[i - 1], waypoints[i]));
  const int count = std::max(1, int(std::ceil(at.back() / spacing - 1e-9)));
  std::vector<Eigen::VectorXd> points;
  size_t i = 1;
  for (int k = 1; k < count; ++k) {
    const double d = at.back() * k / count;
    while (i + 1 < waypoints.size() && at[i] < d) ++i;
    const double length = at[i] - at[i - 1];
    points.push_back(GuideSpace::between(waypoints[i - 1], waypoints[i],
                                         length > 0.0 ? (d - at[i - 1]) / length : 1.0));
  }
  points.push_back(waypoints.back());
  return points;
}

GuideMilestone milestone_at(const GuideSpace& space, const Eigen::VectorXd& x) {
  GuideMilestone m;
  for (size_t k = 0; k < space.moving().size(); ++k) {
    const int e = space.moving()[k];
    GuideMilestone::Root root{e, x.segment<3>(7 * int(k)), std::nullopt, std::nullopt};
    // An object's orientation is part of its task (a ball turned in the hand); a robot's heading
    // follows its feet: stated, it pulls the solver's reference into turns that its stance cannot
    // make (the walk with a turn: no plan in 817 solver calls with headings, 44 without).
    if (space.system().entity(e).kind == EntityKind::Object && space.turns(e))
      root.rpy = base_rpy(x.segment<4>(7 * int(k) + 3));
    m.roots.push_back(root);
  }
  return m;
}

Eigen::Vector3d base_rpy(const Eigen::Vector4d& wxyz) {
  const Eigen::Matrix3d R =
      Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized().matrix();
  return {std::atan2(R(2, 1), R(2, 2)), std::asin(std::clamp(-R(2, 0), -1.0, 1.0)),
          std::atan2(R(1, 0), R(0, 0))};
}

}  // namespace stanceplan
