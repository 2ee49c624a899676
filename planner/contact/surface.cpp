#include "planner/contact/surface.h"

#include <cmath>

namespace stanceplan {
namespace {

double cross2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Default surface x axis: the first link axis not nearly parallel to the normal, projected.
Eigen::Vector3d default_x_axis(const Eigen::Vector3d& n) {
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
    if (std::abs(e.dot(n)) < 0.9) return (e - e.dot(n) * n).normalized();
  }
  return Eigen::Vector3d::UnitX();  // unreachable for a unit n
}

std::string vertex_label(int i) {
  return "vertex " + std::to_string(i);
}

// Strictly convex and counter-clockwise: every turn is a left turn and the turns add up to one
// full revolution (which rules out self-intersecting stars whose turns all have one sign).
bool check_convex_ccw(const std::vector<Eigen::Vector2d>& v, std::string* error) {
  const int n = static_cast<int>(v.size());
  const double scale = [&] {
    double s = 0.0;
    for (const auto& p : v) s = std::max(s, p.norm());
    return std::max(s, 1e-12);
  }();
  for (int i = 0; i < n; ++i) {
    if ((v[(i + 1) % n] - v[i]).norm() < 1e-9 * scale) {
      *error = vertex_label(i) + " and " + vertex_label((i + 1) % n) + " coincide";
      return false;
    }
  }
  double signed_area = 0.0;
  for (int i = 0; i < n; ++i) signed_area += cross2(v[i], v[(i + 1) % n]);
  if (signed_area < 0.0) {
    *error =
        "the vertices are clockwise about the outward normal (expected counter-clockwise: "
        "reverse their order or flip the normal)";
    return false;
  }
  double total_turn = 0.0;
  for (int i = 0; i < n; ++i) {
    const Eigen::Vector2d e1 = v[(i + 1) % n] - v[i];
    const Eigen::Vector2d e2 = v[(i + 2) % n] - v[(i + 1) % n];
    const double turn = cross2(e1, e2);
    if (turn <= 1e-12 * e1.norm() * e2.norm()) {
      *error = "the polygon is not strictly convex at " + vertex_label((i + 1) % n) +
               (std::abs(turn) <= 1e-12 * e1.norm() * e2.norm() ? " (collinear with its neighbours)"
                                                                : " (a right turn)");
      return false;
    }
    total_turn += std::atan2(turn, e1.dot(e2));
  }
  if (std::abs(total_turn - 2.0 * M_PI) > 1e-6) {
    *error = "the polygon winds around itself (self-intersecting)";
    return false;
  }
  return true;
}

}  // namespace

Eigen::Vector3d Surface::vertex_L(int i) const {
  return T_LS * Eigen::Vector3d(vertices_S[i].x(), vertices_S[i].y(), 0.0);
}

std::vector<Eigen::Vector3d> Surface::vertices_L() const {
  std::vector<Eigen::Vector3d> out;
  out.reserve(vertices_S.size());
  for (int i = 0; i < static_cast<int>(vertices_S.size()); ++i) out.push_back(vertex_L(i));
  return out;
}

double Surface::area() const {
  double a = 0.0;
  const int n = static_cast<int>(vertices_S.size());
  for (int i = 0; i < n; ++i) a += cross2(vertices_S[i], vertices_S[(i + 1) % n]);
  return 0.5 * a;
}

Eigen::Vector2d Surface::centroid_S() const {
  if (is_point()) return Eigen::Vector2d::Zero();
  const int n = static_cast<int>(vertices_S.size());
  Eigen::Vector2d c = Eigen::Vector2d::Zero();
  double a2 = 0.0;
  for (int i = 0; i < n; ++i) {
    const double w = cross2(vertices_S[i], vertices_S[(i + 1) % n]);
    c += w * (vertices_S[i] + vertices_S[(i + 1) % n]);
    a2 += w;
  }
  return c / (3.0 * a2);
}

bool make_surface(const std::string& name, int link, const std::string& link_name,
                  const std::vector<Eigen::Vector3d>& vertices_L, const Eigen::Vector3d& normal_L,
                  const Eigen::Vector3d* x_axis_L, Surface* surface, std::string* error,
                  double plane_tolerance) {
  if (vertices_L.size() < 3) {
    *error = "a polygon needs at least 3 vertices, found " + std::to_string(vertices_L.size());
    return false;
  }
  if (!normal_L.allFinite() || normal_L.norm() < 1e-9) {
    *error = "the normal is zero or not finite";
    return false;
  }
  for (const auto& v : vertices_L)
    if (!v.allFinite()) {
      *error = "a vertex is not finite";
      return false;
    }
  const Eigen::Vector3d z = normal_L.normalized();
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  for (const auto& v : vertices_L) center += v;
  center /= static_cast<double>(vertices_L.size());
  int worst = 0;
  double worst_offset = 0.0;
  for (size_t i = 0; i < vertices_L.size(); ++i) {
    const double off = (vertices_L[i] - center).dot(z);
    if (std::abs(off) > std::abs(worst_offset)) {
      worst = static_cast<int>(i);
      worst_offset = off;
    }
  }
  if (std::abs(worst_offset) > plane_tolerance) {
    *error = "not planar: " + vertex_label(worst) + " is " + std::to_string(worst_offset) +
             " m off the plane through the vertex centroid normal to the given normal "
             "(tolerance " +
             std::to_string(plane_tolerance) + " m)";
    return false;
  }
  Eigen::Vector3d x = default_x_axis(z);
  if (x_axis_L) {
    const Eigen::Vector3d projected = *x_axis_L - x_axis_L->dot(z) * z;
    if (!projected.allFinite() || projected.norm() < 1e-6) {
      *error = "x_axis is parallel to the normal";
      return false;
    }
    x = projected.normalized();
  }
  const Eigen::Vector3d y = z.cross(x);
  Surface out;
  out.name = name;
  out.link = link;
  out.link_name = link_name;
  out.T_LS.linear().col(0) = x;
  out.T_LS.linear().col(1) = y;
  out.T_LS.linear().col(2) = z;
  out.T_LS.translation() = center;
  for (const auto& v : vertices_L)
    out.vertices_S.emplace_back((v - center).dot(x), (v - center).dot(y));
  if (!check_convex_ccw(out.vertices_S, error)) return false;
  *surface = std::move(out);
  return true;
}

bool make_point_surface(const std::string& name, int link, const std::string& link_name,
                        const Eigen::Vector3d& p_L, double radius, Surface* surface,
                        std::string* error) {
  if (!p_L.allFinite()) {
    *error = "the point is not finite";
    return false;
  }
  if (!std::isfinite(radius) || radius < 0.0) {
    *error = "the radius must be a length >= 0 (m), found " + std::to_string(radius);
    return false;
  }
  Surface out;
  out.name = name;
  out.link = link;
  out.link_name = link_name;
  out.kind = SurfaceKind::Point;
  out.radius = radius;
  out.T_LS.translation() = p_L;
  out.vertices_S = {Eigen::Vector2d::Zero()};
  *surface = std::move(out);
  return true;
}

}  // namespace stanceplan
