#include "planner/search/step_target.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "planner/contact/polygon.h"

namespace stanceplan {
namespace {

// The largest gap, over the outward normals of a's edges, between a's edge and b's nearest vertex.
double gap_along_edges(const std::vector<Eigen::Vector2d>& a,
                       const std::vector<Eigen::Vector2d>& b) {
  double best = -std::numeric_limits<double>::infinity();
  const size_t n = a.size();
  for (size_t i = 0; i < n; ++i) {
    const Eigen::Vector2d normal = -inward_normal(a[i], a[(i + 1) % n]);
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::Vector2d& p : b) nearest = std::min(nearest, normal.dot(p - a[i]));
    best = std::max(best, nearest);
  }
  return best;
}

Placement along(const Placement& from, const Placement& to, double s) {
  return {from.x + s * (to.x - from.x), from.y + s * (to.y - from.y), to.theta};
}

}  // namespace

std::vector<Eigen::Vector2d> footprint_S2(const Surface& s1, const Placement& placement) {
  if (s1.is_point()) {  // a sphere: the square of half-side r (>= 1 mm) around its contact point
    const double h = std::max(s1.radius, 1e-3);
    return {{placement.x - h, placement.y - h},
            {placement.x + h, placement.y - h},
            {placement.x + h, placement.y + h},
            {placement.x - h, placement.y + h}};
  }
  // s1's x axis lies at theta from s2's; its normal opposes s2's, so its y axis is its x axis
  // turned by -90 deg in s2's plane (the footprint is mirrored), and the order of its vertices
  // reverses to stay counter-clockwise about s2's normal.
  const Eigen::Vector2d x(std::cos(placement.theta), std::sin(placement.theta)), y(x.y(), -x.x());
  const Eigen::Vector2d origin(placement.x, placement.y);
  std::vector<Eigen::Vector2d> out;
  for (auto v = s1.vertices_S.rbegin(); v != s1.vertices_S.rend(); ++v)
    out.push_back(origin + v->x() * x + v->y() * y);
  return out;
}

double footprint_separation(const std::vector<Eigen::Vector2d>& a,
                            const std::vector<Eigen::Vector2d>& b) {
  return std::max(gap_along_edges(a, b), gap_along_edges(b, a));
}

bool footprint_contains(const std::vector<Eigen::Vector2d>& footprint, const Eigen::Vector2d& p) {
  return distance_outside(footprint, p) <= 0.0;
}

Placement step_target(const Scene& scene, const Stance& stance,
                      const std::vector<Placement>& placements, const Contact& added,
                      const Placement& now, const Placement& aim, double share) {
  std::vector<std::vector<Eigen::Vector2d>> others;
  for (int k = 0; k < stance.size(); ++k) {
    const Contact& c = stance.contacts()[k];
    if (c.s2 == added.s2) others.push_back(footprint_S2(scene.surfaces.get(c.s1), placements[k]));
  }
  // The path in twentieths of the step.
  constexpr int kSteps = 20;
  auto point = [&](int k) { return along(now, aim, share * k / kSteps); };
  auto crosses = [&](const Placement& p) {
    return std::any_of(others.begin(), others.end(), [&](const auto& other) {
      return footprint_contains(other, {p.x, p.y});
    });
  };
  const Surface& s1 = scene.surfaces.get(added.s1);
  auto gap = [&](const Placement& p) {
    const auto mine = footprint_S2(s1, p);
    double g = std::numeric_limits<double>::infinity();
    for (const auto& other : others) g = std::min(g, footprint_separation(mine, other));
    return g;
  };
  bool crossing = false;
  for (int k = 1; k <= kSteps && !crossing; ++k) crossing = crosses(point(k));
  if (!crossing) return point(kSteps);
  const double keep = std::min(kStepTargetClearance, gap(now));
  int last = 0;
  while (last < kSteps && gap(point(last + 1)) >= keep) ++last;
  return point(last);
}

Placement landing_estimate(const Scene& scene, const Contact& added, const Placement& now,
                           const Placement& target) {
  const Surface& s1 = scene.surfaces.get(added.s1);
  const std::vector<Eigen::Vector2d>& polygon = scene.surfaces.get(added.s2).vertices_S;
  auto fits = [&](double s) {
    const auto mine = footprint_S2(s1, along(now, target, s));
    return std::all_of(mine.begin(), mine.end(), [&](const Eigen::Vector2d& v) {
      return distance_outside(polygon, v) <= 0.0;
    });
  };
  if (fits(1.0) || !fits(0.0)) return target;
  double in = 0.0, out = 1.0;
  for (int k = 0; k < 20; ++k) {  // to a millionth of the step
    const double mid = 0.5 * (in + out);
    (fits(mid) ? in : out) = mid;
  }
  return along(now, target, in);
}

}  // namespace stanceplan
