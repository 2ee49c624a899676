#include "planner/search/support_share.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace stanceplan {

double support_share_score(const Scene& scene, const std::vector<ModelData>& guide,
                           const Contact& c) {
  const Surface& s1 = scene.surfaces.get(c.s1);
  const Surface& s2 = scene.surfaces.get(c.s2);
  const SurfaceGaps gaps = surface_gaps(scene, guide, c.s1, c.s2);
  const double gap = (1.0 - kShareCentreWeight) * gaps.touching + kShareCentreWeight * gaps.centre;
  // A point contact has no normal of its own (a sphere): its gap alone.
  if (s1.is_point()) return gap;
  const Eigen::Vector3d n1 = guide[c.s1.entity].T_WL[s1.link].linear() * s1.normal_L();
  const Eigen::Vector3d n2 = guide[c.s2.entity].T_WL[s2.link].linear() * s2.normal_L();
  return gap + kShareNormalWeight * (1.0 + n1.dot(n2));  // E8: n1 = -n2 when realised
}

std::vector<double> order_by_support_share(const Scene& scene, const std::vector<ModelData>& guide,
                                           std::vector<Candidate>& candidates, double realised) {
  std::vector<std::pair<double, Candidate>> keyed;
  keyed.reserve(candidates.size());
  for (Candidate& c : candidates)
    keyed.emplace_back(c.add ? support_share_score(scene, guide, c.contact) : 0.0, std::move(c));
  // Realised additions, then removals, then the other additions, whatever their scores.
  const auto group = [realised](const std::pair<double, Candidate>& k) {
    return !k.second.add ? 1 : k.first <= realised ? 0 : 2;
  };
  std::stable_sort(keyed.begin(), keyed.end(), [&](const auto& a, const auto& b) {
    return std::make_pair(group(a), a.first) < std::make_pair(group(b), b.first);
  });
  std::vector<double> scores(keyed.size());
  for (size_t i = 0; i < keyed.size(); ++i) {
    scores[i] = keyed[i].first;
    candidates[i] = std::move(keyed[i].second);
  }
  return scores;
}

}  // namespace stanceplan
