#pragma once
// Planar regions of a triangle mesh (affordances.h): triangles grouped by region growing over
// shared edges. A region starts at the first triangle not yet in one (file order, so the result is
// deterministic) and takes in every edge-adjacent triangle whose normal is within
// `angle_tolerance` of the first one's and whose vertices are within `offset_tolerance` of its
// plane; both are measured against that first triangle, never against the last one taken in, so
// that a gently curved surface does not drift into one region. Triangles meeting only at a vertex,
// or across a T-junction, are not adjacent. Vertices closer than 1 micrometre are welded first
// (STL files repeat every vertex).
#include <Eigen/Geometry>
#include <cmath>
#include <vector>

#include "planner/contact/convex_partition.h"

namespace stanceplan {

struct PlanarRegionOptions {
  double angle_tolerance = 2.0 * M_PI / 180.0;  // rad
  double offset_tolerance = 0.005;              // m
};

// One boundary of a region in its plane: the outer loop counter-clockwise about the region's
// normal, the holes inside it clockwise.
struct RegionOutline {
  Polygon2 outer;
  std::vector<Polygon2> holes;
};

struct PlanarRegion {
  // The plane: through `origin` (the area centroid of the triangles), unit `normal` (their
  // area-weighted mean), 2-D coordinates along x_axis and y_axis (x, y, normal right-handed; x the
  // first of the mesh frame's x, y, z axes not within 25 degrees of the normal, projected).
  Eigen::Vector3d origin = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d x_axis = Eigen::Vector3d::UnitX();
  Eigen::Vector3d y_axis = Eigen::Vector3d::UnitY();
  double area = 0.0;           // of its triangles
  std::vector<int> triangles;  // indices into the input triangles
  // Its boundary loops projected on the plane; several outer loops only when the region touches
  // itself at a vertex.
  std::vector<RegionOutline> outlines;

  Eigen::Vector3d point(const Eigen::Vector2d& p) const {
    return origin + p.x() * x_axis + p.y() * y_axis;
  }
};

// Triangles counter-clockwise seen from outside (mesh_file.h). Degenerate triangles (two welded
// vertices, or no area) belong to no region.
std::vector<PlanarRegion> find_planar_regions(const std::vector<Eigen::Vector3d>& vertices,
                                              const std::vector<Eigen::Vector3i>& triangles,
                                              const PlanarRegionOptions& options = {});

}  // namespace stanceplan
