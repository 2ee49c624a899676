#pragma once
// 3-D convex hull of a point set (qhull, reentrant libqhull_r), as a closed triangulated surface
// suitable for fcl::Convexd: every edge is shared by exactly two triangles, every vertex is used.
#include <Eigen/Core>
#include <vector>

namespace stanceplan {

struct ConvexHull {
  std::vector<Eigen::Vector3d> vertices;   // a subset of the input points
  std::vector<Eigen::Vector3i> triangles;  // counter-clockwise seen from outside
  // One plane per triangle, (n, offset) with |n| = 1 pointing outward: n.x + offset <= 0 inside.
  // Several triangles of one (merged) facet share the facet's plane.
  std::vector<Eigen::Vector4d> planes;
  // Largest Euclidean distance from an input point to the hull: 0 (up to round-off) for an exact
  // hull; up to about simplify_tolerance for a simplified one. The hull grown by this distance
  // (its Minkowski sum with a ball) contains every input point.
  double max_outside_distance = 0.0;
};

struct ConvexHullOptions {
  // Flat input (all points within a plane or on a line, e.g. a zero-thickness plate) has no
  // 3-D hull. When this is > 0, such input is thickened: every point is copied +-thickness/2
  // along the missing direction(s), giving a thin slab (or prism) that still contains the points.
  // When 0, flat input throws.
  double degenerate_thickness = 1e-4;
  // When > 0, points less than this far above a facet do not become vertices (qhull option W):
  // far fewer vertices on finely tessellated curved surfaces, at the price of input points up to
  // about this far outside the hull (see ConvexHull::max_outside_distance).
  double simplify_tolerance = 0.0;
};

// Throws std::invalid_argument on fewer than one distinct point, on non-finite coordinates, on
// flat input when degenerate_thickness is 0, or when qhull fails (with qhull's message).
ConvexHull convex_hull(const std::vector<Eigen::Vector3d>& points,
                       const ConvexHullOptions& options = {});

}  // namespace stanceplan
