#pragma once
// Convex polygons in a surface's plane (surface vertices are counter-clockwise about its normal):
// the edge normals and point-outside distance that the polygon constraint (E10-E11 relaxed, case
// 1), the certifier and the search's step targets share.
#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <vector>

namespace stanceplan {

// Unit normal of the edge a -> b of a counter-clockwise polygon, pointing inside (left of it).
inline Eigen::Vector2d inward_normal(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d edge = (b - a).normalized();
  return {-edge.y(), edge.x()};
}

// How far p lies beyond the farthest edge line of the convex polygon: > 0 outside, <= 0 inside.
inline double distance_outside(const std::vector<Eigen::Vector2d>& polygon,
                               const Eigen::Vector2d& p) {
  double outside = -std::numeric_limits<double>::infinity();
  for (size_t e = 0; e < polygon.size(); ++e) {
    const Eigen::Vector2d& a = polygon[e];
    outside = std::max(outside, -inward_normal(a, polygon[(e + 1) % polygon.size()]).dot(p - a));
  }
  return outside;
}

}  // namespace stanceplan
