#include "planner/contact/hull_face.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>

#include "planner/contact/polygon.h"

namespace stanceplan {
namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// One half of Andrew's chain over the sorted points: each point is kept only after a strict left
// turn, so collinear points are dropped.
void add_to_chain(const Eigen::Vector2d& p, Polygon2* chain, size_t floor) {
  while (chain->size() >= floor + 2 &&
         cross2((*chain)[chain->size() - 1] - (*chain)[chain->size() - 2],
                p - (*chain)[chain->size() - 1]) <= 0.0)
    chain->pop_back();
  chain->push_back(p);
}

PlanarFace face_from_2d(const PlaneBasis& basis, double offset, const Polygon2& polygon) {
  PlanarFace face;
  face.normal = basis.n;
  face.offset = offset;
  for (const Eigen::Vector2d& p : polygon)
    face.vertices.push_back(offset * basis.n + p.x() * basis.u + p.y() * basis.v);
  return face;
}

Polygon2 face_to_2d(const PlaneBasis& basis, const PlanarFace& face) {
  Polygon2 polygon;
  for (const Eigen::Vector3d& p : face.vertices) polygon.push_back(basis.to_2d(p));
  return polygon;
}

// A triangle's outward normal candidate: its unit normal (either side), how near it is to the
// wanted direction (its cosine) and a point of its plane.
struct NormalCandidate {
  double cosine;
  Eigen::Vector3d normal;
  Eigen::Vector3d point;
};

}  // namespace

Polygon2 convex_hull_2d(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y());
  });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  Polygon2 hull;
  for (const Eigen::Vector2d& p : points) add_to_chain(p, &hull, 0);  // lower chain
  const size_t lower = hull.size() - 1;
  for (auto p = points.rbegin() + 1; p != points.rend(); ++p) add_to_chain(*p, &hull, lower);
  hull.pop_back();  // the first point again
  return hull;
}

PlaneBasis plane_basis(const Eigen::Vector3d& n) {
  PlaneBasis basis;
  basis.n = n;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
    if (std::abs(e.dot(n)) < 0.9) {
      basis.u = (e - e.dot(n) * n).normalized();
      break;
    }
  }
  basis.v = n.cross(basis.u);
  return basis;
}

PlanarFace support_face(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& normal,
                        double flatness, double collinear_tolerance) {
  const PlaneBasis basis = plane_basis(normal);
  double offset = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& p : points) offset = std::max(offset, normal.dot(p));
  std::vector<Eigen::Vector2d> on_plane;
  for (const Eigen::Vector3d& p : points)
    if (normal.dot(p) >= offset - flatness) on_plane.push_back(basis.to_2d(p));
  const Polygon2 polygon = simplify_polygon(convex_hull_2d(on_plane), collinear_tolerance);
  return face_from_2d(basis, offset, polygon);
}

std::optional<Eigen::Vector3d> nearest_hull_normal(const std::vector<Eigen::Vector3d>& vertices,
                                                   const std::vector<Eigen::Vector3i>& triangles,
                                                   const Eigen::Vector3d& direction,
                                                   double tolerance) {
  const Eigen::Vector3d d = direction.normalized();
  std::vector<NormalCandidate> candidates;
  for (const Eigen::Vector3i& t : triangles) {
    const Eigen::Vector3d &a = vertices[t[0]], &b = vertices[t[1]], &c = vertices[t[2]];
    const Eigen::Vector3d cross = (b - a).cross(c - a);
    const double longest =
        std::max({(b - a).squaredNorm(), (c - b).squaredNorm(), (a - c).squaredNorm()});
    // Slivers (height under 1e-6 of the longest edge) have no reliable normal.
    if (!(cross.norm() > 1e-6 * longest)) continue;
    const Eigen::Vector3d n = cross.normalized();
    candidates.push_back({n.dot(d), n, a});
    candidates.push_back({-n.dot(d), -n, a});
  }
  // Nearest first; the first one on the hull is the answer.
  std::stable_sort(
      candidates.begin(), candidates.end(),
      [](const NormalCandidate& x, const NormalCandidate& y) { return x.cosine > y.cosine; });
  for (const NormalCandidate& candidate : candidates) {
    const double offset = candidate.normal.dot(candidate.point) + tolerance;
    if (std::all_of(vertices.begin(), vertices.end(),
                    [&](const Eigen::Vector3d& p) { return candidate.normal.dot(p) <= offset; }))
      return candidate.normal;
  }
  return std::nullopt;
}

PlanarFace inset_face(const PlanarFace& face, double margin, double collinear_tolerance) {
  const PlaneBasis basis = plane_basis(face.normal);
  const Polygon2 inset = inset_convex_polygon(face_to_2d(basis, face), margin);
  return face_from_2d(basis, face.offset, simplify_polygon(inset, collinear_tolerance));
}

double narrowest_width(const PlanarFace& face) {
  const Polygon2 polygon = face_to_2d(plane_basis(face.normal), face);
  double narrowest = std::numeric_limits<double>::infinity();
  for (size_t e = 0; e < polygon.size(); ++e) {
    const Eigen::Vector2d& a = polygon[e];
    const Eigen::Vector2d inward = inward_normal(a, polygon[(e + 1) % polygon.size()]);
    double width = 0.0;
    for (const Eigen::Vector2d& p : polygon) width = std::max(width, inward.dot(p - a));
    narrowest = std::min(narrowest, width);
  }
  return narrowest;
}

}  // namespace stanceplan
