#include "planner/collision/polytope_penetration.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace stanceplan {
namespace {

// Index of the vertex maximising direction . v.
int support_index(const std::vector<Eigen::Vector3d>& vertices, const Eigen::Vector3d& direction) {
  int best = 0;
  double best_value = -std::numeric_limits<double>::infinity();
  for (int i = 0; i < static_cast<int>(vertices.size()); ++i) {
    const double value = direction.dot(vertices[i]);
    if (value > best_value) {
      best_value = value;
      best = i;
    }
  }
  return best;
}

// True when the Gauss-map arcs (a, b) and (c, d) cross, given a_x_b = a x b and c_x_d = c x d:
// c and d on either side of the great circle through a and b, a and b on either side of the one
// through c and d, and the crossing on the same hemisphere for both arcs (not antipodal).
bool arcs_cross(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& a_x_b,
                const Eigen::Vector3d& c, const Eigen::Vector3d& d, const Eigen::Vector3d& c_x_d) {
  const double c_side = c.dot(a_x_b), d_side = d.dot(a_x_b);
  if (c_side * d_side >= 0.0) return false;
  const double a_side = a.dot(c_x_d), b_side = b.dot(c_x_d);
  return a_side * b_side < 0.0 && c_side * b_side > 0.0;
}

enum class Feature { FaceA, FaceB, Edges };

// The best (smallest-overlap) axis found so far, in A's frame.
struct Axis {
  double overlap = std::numeric_limits<double>::infinity();
  Feature feature = Feature::FaceA;
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();  // from A to B
  Eigen::Vector3d p_A = Eigen::Vector3d::Zero();      // support point of A along normal
  Eigen::Vector3d p_B = Eigen::Vector3d::Zero();      // support point of B along -normal
};

// Faces of A: d = n; overlap = h_A(n) + h_B(-n), B's vertices mapped by (R, t) into A's frame.
void try_faces_of_a(const ConvexPolytope& A, const ConvexPolytope& B, const Eigen::Matrix3d& R,
                    const Eigen::Vector3d& t, Axis* best) {
  for (const ConvexPolytope::Plane& plane : A.planes) {
    const Eigen::Vector3d minus_n_B = -(R.transpose() * plane.normal);
    const int b = support_index(B.vertices, minus_n_B);
    const Eigen::Vector3d p_B = R * B.vertices[b] + t;
    const double overlap = plane.support - plane.normal.dot(p_B);
    if (overlap < best->overlap) {
      *best = {overlap, Feature::FaceA, plane.normal, p_B + overlap * plane.normal, p_B};
    }
  }
}

// Faces of B (normal m, R m in A's frame): d = -R m; overlap = h_A(-R m) + h_B(R m).
void try_faces_of_b(const ConvexPolytope& A, const ConvexPolytope& B, const Eigen::Matrix3d& R,
                    const Eigen::Vector3d& t, Axis* best) {
  for (const ConvexPolytope::Plane& plane : B.planes) {
    const Eigen::Vector3d m = R * plane.normal;
    const int a = support_index(A.vertices, -m);
    const Eigen::Vector3d& p_A = A.vertices[a];
    const double overlap = plane.support + m.dot(t) - m.dot(p_A);
    if (overlap < best->overlap) {
      *best = {overlap, Feature::FaceB, -m, p_A, p_A + overlap * m};
    }
  }
}

// Closest points of the lines p + s u and q + r v (clamped to the segments s, r in [0, 1]).
void closest_on_segments(const Eigen::Vector3d& p, const Eigen::Vector3d& u,
                         const Eigen::Vector3d& q, const Eigen::Vector3d& v, Eigen::Vector3d* on_p,
                         Eigen::Vector3d* on_q) {
  const Eigen::Vector3d w = p - q;
  const double uu = u.dot(u), uv = u.dot(v), vv = v.dot(v), uw = u.dot(w), vw = v.dot(w);
  const double denominator = uu * vv - uv * uv;
  double s = 0.0, r = 0.0;
  if (denominator > 1e-300) {
    s = std::clamp((uv * vw - vv * uw) / denominator, 0.0, 1.0);
    r = std::clamp((uu * vw - uv * uw) / denominator, 0.0, 1.0);
  }
  *on_p = p + s * u;
  *on_q = q + r * v;
}

// Lower bound of h_X(u) + h_Y(-u) over the directions u of an edge's Gauss-map arc (n0, n1):
// u = a n0 + b n1 with a, b >= 0 and a + b >= 1, the edge's point p gives h_X(u) = u . p, and
// h_Y(-u) >= -u . c_Y + r_Y (c_Y, r_Y: Y's centre and inradius). Valid when both arc-end values
// are >= 0, which is all the pruning needs.
bool edge_cannot_beat(const Eigen::Vector3d& n0, const Eigen::Vector3d& n1,
                      const Eigen::Vector3d& p_minus_center, double inradius, double best) {
  const double low = std::min(n0.dot(p_minus_center), n1.dot(p_minus_center));
  return low >= 0.0 && low + inradius >= best;
}

// Edge pairs whose Gauss-map arcs cross (A's arc (n0, n1), -B's arc (-R n0, -R n1)): d = e_A x e_B.
void try_edge_pairs(const ConvexPolytope& A, const ConvexPolytope& B, const Eigen::Matrix3d& R,
                    const Eigen::Vector3d& t, PenetrationScratch& scratch, Axis* best) {
  const Eigen::Vector3d center_B = R * B.center + t;
  scratch.b_edges.clear();
  for (const ConvexPolytope::Edge& eb : B.edges) {
    PenetrationScratch::EdgeInA e;
    e.c = -(R * eb.n0);
    e.d = -(R * eb.n1);
    e.q = R * B.vertices[eb.v0] + t;
    if (edge_cannot_beat(e.c, e.d, A.center - e.q, A.inradius, best->overlap)) continue;
    e.c_x_d = R * eb.arc_normal;  // (-R n0) x (-R n1) = R (n0 x n1)
    e.v = R * (B.vertices[eb.v1] - B.vertices[eb.v0]);
    scratch.b_edges.push_back(e);
  }
  for (const ConvexPolytope::Edge& ea : A.edges) {
    const Eigen::Vector3d& p = A.vertices[ea.v0];
    if (edge_cannot_beat(ea.n0, ea.n1, p - center_B, B.inradius, best->overlap)) continue;
    const Eigen::Vector3d u = A.vertices[ea.v1] - p;
    for (const PenetrationScratch::EdgeInA& eb : scratch.b_edges) {
      if (!arcs_cross(ea.n0, ea.n1, ea.arc_normal, eb.c, eb.d, eb.c_x_d)) continue;
      Eigen::Vector3d axis = u.cross(eb.v);
      const double length = axis.norm();
      if (length <= 1e-12 * u.norm() * eb.v.norm()) continue;  // parallel: covered by the faces
      axis /= length;
      if (axis.dot(ea.n0 + ea.n1) < 0.0) axis = -axis;  // outward of A
      const double overlap = axis.dot(p - eb.q);
      if (overlap < best->overlap) {
        Eigen::Vector3d on_a, on_b;
        closest_on_segments(p, u, eb.q, eb.v, &on_a, &on_b);
        *best = {overlap, Feature::Edges, axis, on_a, on_a - overlap * axis};
      }
    }
  }
}

void set_center_and_inradius(ConvexPolytope* polytope) {
  polytope->center.setZero();
  for (const Eigen::Vector3d& v : polytope->vertices) polytope->center += v;
  polytope->center /= static_cast<double>(polytope->vertices.size());
  polytope->inradius = std::numeric_limits<double>::infinity();
  for (const ConvexPolytope::Plane& plane : polytope->planes) {
    polytope->inradius =
        std::min(polytope->inradius, plane.support - plane.normal.dot(polytope->center));
  }
  polytope->inradius = std::max(polytope->inradius, 0.0);
}

}  // namespace

ConvexPolytope polytope_from_hull(const ConvexHull& hull) {
  ConvexPolytope polytope;
  polytope.vertices = hull.vertices;
  // Triangles of one (merged) qhull facet share its plane exactly: one plane each, and the edges
  // between them are not edges of the polytope.
  std::map<std::array<double, 4>, int> plane_index;
  std::vector<int> plane_of_triangle;
  for (const Eigen::Vector4d& p : hull.planes) {
    const std::array<double, 4> key{p[0], p[1], p[2], p[3]};
    auto [it, inserted] = plane_index.emplace(key, static_cast<int>(polytope.planes.size()));
    if (inserted) {
      const Eigen::Vector3d normal = p.head<3>().normalized();
      const int top = support_index(hull.vertices, normal);
      polytope.planes.push_back({normal, normal.dot(hull.vertices[top])});
    }
    plane_of_triangle.push_back(it->second);
  }
  std::map<std::pair<int, int>, int> first_plane_of_edge;
  for (size_t f = 0; f < hull.triangles.size(); ++f) {
    for (int k = 0; k < 3; ++k) {
      const int v0 = hull.triangles[f][k], v1 = hull.triangles[f][(k + 1) % 3];
      const auto key = std::minmax(v0, v1);
      auto [it, inserted] = first_plane_of_edge.emplace(key, plane_of_triangle[f]);
      if (inserted || it->second == plane_of_triangle[f]) continue;
      const Eigen::Vector3d& n0 = polytope.planes[it->second].normal;
      const Eigen::Vector3d& n1 = polytope.planes[plane_of_triangle[f]].normal;
      polytope.edges.push_back({key.first, key.second, n0, n1, n0.cross(n1)});
    }
  }
  set_center_and_inradius(&polytope);
  return polytope;
}

ConvexPolytope polytope_from_box(const Eigen::Vector3d& size) {
  ConvexPolytope box;
  const Eigen::Vector3d half = 0.5 * size;
  auto sign = [](int vertex, int axis) { return (vertex >> axis) & 1 ? 1.0 : -1.0; };
  for (int i = 0; i < 8; ++i) {
    box.vertices.emplace_back(sign(i, 0) * half.x(), sign(i, 1) * half.y(), sign(i, 2) * half.z());
  }
  for (int axis = 0; axis < 3; ++axis) {
    for (double s : {1.0, -1.0}) {
      box.planes.push_back({s * Eigen::Vector3d::Unit(axis), half[axis]});
    }
  }
  // An edge along `axis` joins vertices differing in that bit only; its faces are the other two
  // axes' faces on the sides of its vertices.
  for (int i = 0; i < 8; ++i) {
    for (int axis = 0; axis < 3; ++axis) {
      const int j = i | (1 << axis);
      if (j == i) continue;
      const int a = (axis + 1) % 3, b = (axis + 2) % 3;
      const Eigen::Vector3d n0 = sign(i, a) * Eigen::Vector3d::Unit(a);
      const Eigen::Vector3d n1 = sign(i, b) * Eigen::Vector3d::Unit(b);
      box.edges.push_back({i, j, n0, n1, n0.cross(n1)});
    }
  }
  set_center_and_inradius(&box);
  return box;
}

Penetration polytope_penetration(const ConvexPolytope& A, const Eigen::Isometry3d& T_WA,
                                 const ConvexPolytope& B, const Eigen::Isometry3d& T_WB,
                                 PenetrationScratch& scratch) {
  const Eigen::Isometry3d T_AB = T_WA.inverse() * T_WB;
  const Eigen::Matrix3d R = T_AB.linear();
  const Eigen::Vector3d t = T_AB.translation();
  Axis best;
  try_faces_of_a(A, B, R, t, &best);
  try_faces_of_b(A, B, R, t, &best);
  try_edge_pairs(A, B, R, t, scratch, &best);
  Penetration out;
  out.depth = best.overlap;
  out.normal_W = T_WA.linear() * best.normal;
  out.p_A_W = T_WA * best.p_A;
  out.p_B_W = T_WA * best.p_B;
  return out;
}

}  // namespace stanceplan
