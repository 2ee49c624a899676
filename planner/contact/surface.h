#pragma once
// A contact surface (docs/METHOD.md section 2): a planar convex polygon fixed to a link, with a
// frame whose z axis is the outward normal. Surfaces are value types shared by the solver, the plan
// writer and the renderer.
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace stanceplan {

struct Surface {
  std::string name;  // unique within its model, e.g. "l_sole"
  int link = -1;     // index into Model::links
  std::string link_name;
  // Surface frame in the link frame: origin O_s, columns x_s, y_s, z_s (z_s = outward normal).
  Eigen::Isometry3d T_LS = Eigen::Isometry3d::Identity();
  // Polygon in the surface frame's (x_s, y_s) plane, counter-clockwise about z_s.
  std::vector<Eigen::Vector2d> vertices_S;

  Eigen::Vector3d normal_L() const { return T_LS.linear().col(2); }
  Eigen::Vector3d vertex_L(int i) const;  // vertex i in the link frame
  std::vector<Eigen::Vector3d> vertices_L() const;
  double area() const;
  Eigen::Vector2d centroid_S() const;  // area centroid in the surface plane
};

// Builds a surface from 3-D vertices in the link frame and the outward normal (link frame).
// Validates: >= 3 vertices, planar within plane_tolerance, strictly convex, counter-clockwise
// about the normal, non-degenerate. The frame: z_s = normal, origin = vertex centroid, x_s = the
// first of the link's x, y, z axes (projected) not parallel to the normal, unless x_axis is given.
// On a fault returns false and fills *error with what is wrong (no file context; callers add it).
bool make_surface(const std::string& name, int link, const std::string& link_name,
                  const std::vector<Eigen::Vector3d>& vertices_L, const Eigen::Vector3d& normal_L,
                  const Eigen::Vector3d* x_axis_L, Surface* surface, std::string* error,
                  double plane_tolerance = 1e-6);

}  // namespace stanceplan
