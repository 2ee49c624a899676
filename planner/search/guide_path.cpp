#include "planner/search/guide_path.h"

#include <algorithm>
#include <cmath>

namespace stanceplan {

GuidePath::GuidePath(const System& system, std::vector<Eigen::VectorXd> milestones,
                     std::vector<Eigen::VectorXd> masks, GuideMetric metric)
    : system_(system),
      milestones_(std::move(milestones)),
      masks_(std::move(masks)),
      metric_(metric) {}

double GuidePath::distance_to(const Eigen::VectorXd& q, int t) const {
  return distance(q, milestones_.at(t), t < int(masks_.size()) ? &masks_[t] : nullptr);
}

Eigen::VectorXd GuidePath::posture_near(const Eigen::VectorXd& q, int t) const {
  const Eigen::VectorXd& m = milestones_.at(t);
  if (t >= int(masks_.size()) || masks_[t].size() != q.size()) return m;
  Eigen::VectorXd out = q;
  for (Eigen::Index i = 0; i < q.size(); ++i)
    if (masks_[t][i] > 0.0) out[i] = m[i];
  return out;
}

bool GuidePath::same_entries(int t, int u) const {
  const auto mask = [&](int m) -> const Eigen::VectorXd* {
    return m < int(masks_.size()) && masks_[size_t(m)].size() > 0 ? &masks_[size_t(m)] : nullptr;
  };
  const Eigen::VectorXd *a = mask(t), *b = mask(u);
  if (a == nullptr && b == nullptr) return true;
  if (a == nullptr || b == nullptr) return ((a ? *a : *b).array() > 0.0).all();  // none: every one
  return ((a->array() > 0.0) == (b->array() > 0.0)).all();
}

double GuidePath::distance(const Eigen::VectorXd& a, const Eigen::VectorXd& b,
                           const Eigen::VectorXd* mask) const {
  auto stated = [&](int i) { return mask == nullptr || (*mask)[i] > 0.0; };
  double sum = 0.0;
  for (int e = 0; e < system_.num_entities(); ++e) {
    const Entity& entity = system_.entity(e);
    const int o = system_.offset(e);
    if (entity.floating()) {
      for (int i = 0; i < 3; ++i)
        if (stated(o + i)) sum += std::pow(metric_.position * (a[o + i] - b[o + i]), 2);
      if (stated(o + 3)) {
        const Eigen::Vector4d qa = a.segment<4>(o + 3).normalized(),
                              qb = b.segment<4>(o + 3).normalized();
        const double angle =
            2.0 * std::acos(std::min(1.0, std::abs(qa.dot(qb))));  // q and -q: one rotation
        sum += std::pow(metric_.orientation * angle, 2);
      }
    }
    const int first = o + entity.first_dof();
    for (int k = 0; k < entity.model->num_dofs(); ++k)
      if (stated(first + k)) sum += std::pow(metric_.joints * (a[first + k] - b[first + k]), 2);
  }
  return std::sqrt(sum);
}

}  // namespace stanceplan
