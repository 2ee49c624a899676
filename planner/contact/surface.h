#pragma once
// A contact surface (docs/METHOD.md section 2): a planar convex polygon fixed to a link, with a
// frame whose z axis is the outward normal, or a point surface: a sphere of some radius at a point
// of a link (a round fingertip), which touches polygons only. Surfaces are value types shared by
// the solver, the plan writer and the renderer.
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace stanceplan {

enum class SurfaceKind { Polygon, Point };

struct Surface {
  std::string name;  // unique within its model, e.g. "l_sole"
  int link = -1;     // index into Model::links
  std::string link_name;
  // Surface frame in the link frame: origin O_s, columns x_s, y_s, z_s (z_s = outward normal).
  Eigen::Isometry3d T_LS = Eigen::Isometry3d::Identity();
  // Polygon in the surface frame's (x_s, y_s) plane, counter-clockwise about z_s.
  std::vector<Eigen::Vector2d> vertices_S;
  // A point surface: a sphere of `radius` centred at T_LS's origin p_L, T_LS's rotation the
  // identity (a sphere has no normal of its own), and vertices_S the single vertex (0, 0), the
  // centre. The centre stands for the polygon's vertices wherever s1's vertices are used: its
  // (x, y) in s2's frame is that of the contact point c - r z_s2, so the polygon rows (case 1) and
  // the placement rows (E10-E11) hold unchanged; E9 becomes (c - O_s2) . z_s2 = r; E8, E12 and
  // E13 do not apply; the one force acts at c - r z_s2, not at the centre.
  SurfaceKind kind = SurfaceKind::Polygon;
  double radius = 0.0;

  bool is_point() const { return kind == SurfaceKind::Point; }
  Eigen::Vector3d center_L() const { return T_LS.translation(); }  // a point surface's centre

  Eigen::Vector3d normal_L() const { return T_LS.linear().col(2); }
  Eigen::Vector3d vertex_L(int i) const;  // vertex i in the link frame
  std::vector<Eigen::Vector3d> vertices_L() const;
  double area() const;                 // 0 for a point surface
  Eigen::Vector2d centroid_S() const;  // area centroid in the surface plane; (0, 0) for a point
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

// Builds a point surface: a sphere of `radius` (>= 0, m; 0 is a sharp tip) centred at p_L (link
// frame). On a fault (not finite, negative radius) returns false and fills *error.
bool make_point_surface(const std::string& name, int link, const std::string& link_name,
                        const Eigen::Vector3d& p_L, double radius, Surface* surface,
                        std::string* error);

}  // namespace stanceplan
