#include "planner/guide/guide_space.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace stanceplan {
namespace {

Eigen::Quaterniond quaternion(const Eigen::Ref<const Eigen::VectorXd>& wxyz) {
  return Eigen::Quaterniond(wxyz[0], wxyz[1], wxyz[2], wxyz[3]).normalized();
}

double rotation_angle(const Eigen::VectorXd& a, const Eigen::VectorXd& b, int o) {
  return quaternion(a.segment<4>(o)).angularDistance(quaternion(b.segment<4>(o)));
}

}  // namespace

GuideSpace::GuideSpace(const System& system, Eigen::VectorXd q_start, Eigen::VectorXd q_goal)
    : system_(system), q_start_(std::move(q_start)), q_goal_(std::move(q_goal)) {
  for (int e = 0; e < system.num_entities(); ++e) {
    if (!system.entity(e).floating()) continue;
    const int o = system.offset(e);
    const double moved = (q_goal_.segment<3>(o) - q_start_.segment<3>(o)).norm();
    if (moved > 1e-3 || rotation_angle(q_start_, q_goal_, o + Entity::kBaseQuaternion) > 1e-3)
      moving_.push_back(e);
  }
}

Eigen::VectorXd GuideSpace::point_of(const Eigen::VectorXd& q, double s) const {
  Eigen::VectorXd x(size());
  for (size_t k = 0; k < moving_.size(); ++k)
    x.segment<7>(7 * int(k)) = q.segment<7>(system_.offset(moving_[k]));
  x[size() - 1] = s;
  return x;
}

void GuideSpace::configuration(const Eigen::VectorXd& x, Eigen::VectorXd& q) const {
  const double s = std::clamp(x[size() - 1], 0.0, 1.0);
  q = q_start_ + s * (q_goal_ - q_start_);  // joints: a straight line between the postures
  for (int e = 0; e < system_.num_entities(); ++e)
    if (system_.entity(e).floating())  // roots that do not move stay where they start
      q.segment<7>(system_.offset(e)) = q_start_.segment<7>(system_.offset(e));
  for (size_t k = 0; k < moving_.size(); ++k) {
    const int o = system_.offset(moving_[k]);
    q.segment<3>(o) = x.segment<3>(7 * int(k));
    const Eigen::Quaterniond r = quaternion(x.segment<4>(7 * int(k) + 3));
    q.segment<4>(o + Entity::kBaseQuaternion) << r.w(), r.x(), r.y(), r.z();
  }
}

Eigen::VectorXd GuideSpace::between(const Eigen::VectorXd& a, const Eigen::VectorXd& b, double t) {
  Eigen::VectorXd x = a + t * (b - a);
  for (int o = 0; o + 7 < int(a.size()); o += 7) {
    const Eigen::Quaterniond qa = quaternion(a.segment<4>(o + 3));
    const Eigen::Quaterniond q = qa.slerp(t, quaternion(b.segment<4>(o + 3)));
    x.segment<4>(o + 3) << q.w(), q.x(), q.y(), q.z();
  }
  return x;
}

double GuideSpace::travel(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  if (moving_.empty()) return std::abs(b[size() - 1] - a[size() - 1]);
  double d = 0.0;
  for (size_t k = 0; k < moving_.size(); ++k) {
    const int o = 7 * int(k);
    d = std::max(d, (b.segment<3>(o) - a.segment<3>(o)).norm() +
                        kTurnLength * rotation_angle(a, b, o + Entity::kBaseQuaternion));
  }
  return d;
}

bool GuideSpace::turns(int e) const {
  return rotation_angle(q_start_, q_goal_, system_.offset(e) + Entity::kBaseQuaternion) > 0.1;
}

}  // namespace stanceplan
