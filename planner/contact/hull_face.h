#pragma once
// Flat faces of the convex hull of a point set, found without building the 3-D hull (the hulls of
// planner/collision/ sit beside this layer, not below it): the face with a given outward normal is
// the 2-D convex hull of the points on the support plane of that normal, and the hull's facets are
// looked for among a mesh's own triangles. Used by the link faces of surface files (link_faces.h);
// shared with any reader of flat faces from geometry.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "planner/contact/convex_partition.h"

namespace stanceplan {

// Andrew's monotone chain: the convex hull of the points, counter-clockwise, without repeated or
// collinear vertices. Fewer than 3 vertices when the points are all on one line.
Polygon2 convex_hull_2d(std::vector<Eigen::Vector2d> points);

// An orthonormal basis (u, v) of the plane normal to the unit vector n, with u x v = n: a polygon
// counter-clockwise in (u, v) coordinates is counter-clockwise about n.
struct PlaneBasis {
  Eigen::Vector3d u, v, n;
  Eigen::Vector2d to_2d(const Eigen::Vector3d& p) const { return {u.dot(p), v.dot(p)}; }
};
PlaneBasis plane_basis(const Eigen::Vector3d& n);

// A convex planar polygon in 3-D.
struct PlanarFace {
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // unit, outward
  double offset = 0.0;                                // the plane: normal . p = offset
  std::vector<Eigen::Vector3d> vertices;  // on the plane, counter-clockwise about the normal, >= 3
                                          // (empty: no face)
};

// The face of the points' convex hull whose outward normal is `normal` (unit): the points within
// `flatness` (m) of their support plane along it (the plane of the outermost points), projected
// onto that plane, and the convex hull of those, without the vertices that lie within
// `collinear_tolerance` (m) of the line through their neighbours (simplify_polygon). No vertices
// when fewer than 3 are left: the points touch that plane along a line or at one point.
PlanarFace support_face(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& normal,
                        double flatness, double collinear_tolerance);

// Among the mesh's triangles that lie on the convex hull of its vertices (none of them more than
// `tolerance` (m) beyond the triangle's plane), the outward unit normal nearest `direction`. The
// winding is not trusted: either side of a triangle is outward when no vertex lies beyond it.
// Nothing when no triangle with an area lies on the hull (a hull facet that only bridges over a
// concavity, touching the mesh along edges or at vertices, holds no triangle of the mesh and is not
// a flat face of it).
std::optional<Eigen::Vector3d> nearest_hull_normal(const std::vector<Eigen::Vector3d>& vertices,
                                                   const std::vector<Eigen::Vector3i>& triangles,
                                                   const Eigen::Vector3d& direction,
                                                   double tolerance);

// The face with every edge moved inward by `margin` (m) in its plane (inset_convex_polygon), then
// without the vertices within `collinear_tolerance` (m) of the line through their neighbours: no
// vertices when nothing is left.
PlanarFace inset_face(const PlanarFace& face, double margin, double collinear_tolerance);

// The face's width along its narrowest direction: the smallest, over its edges, of the largest
// distance of a vertex from the edge's line. An inset of half of it or more leaves nothing.
double narrowest_width(const PlanarFace& face);

}  // namespace stanceplan
