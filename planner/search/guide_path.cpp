#include "planner/search/guide_path.h"

#include <algorithm>
#include <cmath>

namespace stanceplan {

GuidePath::GuidePath(const System& system, std::vector<Eigen::VectorXd> milestones, GuideMetric metric)
    : system_(system), milestones_(std::move(milestones)), metric_(metric) {}

double GuidePath::distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b) const {
  double sum = 0.0;
  for (int e = 0; e < system_.num_entities(); ++e) {
    const Entity& entity = system_.entity(e);
    const int o = system_.offset(e);
    if (entity.floating()) {
      sum += std::pow(metric_.position * (a.segment<3>(o) - b.segment<3>(o)).norm(), 2);
      const Eigen::Vector4d qa = a.segment<4>(o + 3).normalized(), qb = b.segment<4>(o + 3).normalized();
      const double angle = 2.0 * std::acos(std::min(1.0, std::abs(qa.dot(qb))));  // q and -q: one rotation
      sum += std::pow(metric_.orientation * angle, 2);
    }
    const int first = o + entity.first_dof();
    const int n = entity.model->num_dofs();
    sum += std::pow(metric_.joints, 2) * (a.segment(first, n) - b.segment(first, n)).squaredNorm();
  }
  return std::sqrt(sum);
}

}  // namespace stanceplan
