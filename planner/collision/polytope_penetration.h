#pragma once
// Exact penetration depth of two overlapping convex polytopes by the separating-axis theorem, used
// instead of FCL's EPA: FCL 0.7's EPA aborts the whole process (assert in ComputeVisiblePatch;
// Debian builds libfcl with asserts on) on nearly parallel faces, e.g. a slightly tilted box
// resting 1e-7..1e-2 m deep in a floor, i.e. every stance's contacts. The penetration depth is the
// smallest overlap h_A(d) + h_B(-d) over the facet normals d of the Minkowski sum A + (-B): the
// face normals of A, the (negated) face normals of B, and the cross products of the edge pairs of
// A and B whose arcs cross on the Gauss map.
#include <Eigen/Geometry>
#include <vector>

#include "planner/collision/convex_hull.h"

namespace stanceplan {

// A convex polytope in its own frame, with what the separating-axis test needs.
struct ConvexPolytope {
  struct Plane {
    Eigen::Vector3d normal;  // unit, outward
    double support;          // max over the vertices of normal . v
  };
  // An edge between two faces that are not coplanar, with their outward normals n0, n1 and
  // arc_normal = n0 x n1 (the plane of the edge's arc on the Gauss map).
  struct Edge {
    int v0, v1;
    Eigen::Vector3d n0, n1, arc_normal;
  };
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Plane> planes;  // one per distinct face plane
  std::vector<Edge> edges;
  // Mean of the vertices, and its distance to the nearest face plane: every support value
  // h(u) >= u . center + inradius, which lets the edge loop skip edges that cannot win.
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  double inradius = 0.0;
};

ConvexPolytope polytope_from_hull(const ConvexHull& hull);
ConvexPolytope polytope_from_box(const Eigen::Vector3d& size);  // full side lengths, centred

struct Penetration {
  double depth = 0.0;  // >= 0 when they overlap (a tiny negative value: they barely do not)
  // Unit, from A to B: translating B by depth * normal_W separates them.
  Eigen::Vector3d normal_W = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d p_A_W = Eigen::Vector3d::Zero();  // A's point deepest inside B
  Eigen::Vector3d p_B_W = Eigen::Vector3d::Zero();  // B's point deepest inside A
};

// Work buffer of polytope_penetration (B's candidate edges in A's frame); reserve it for the
// largest edge count and the queries allocate nothing.
struct PenetrationScratch {
  struct EdgeInA {
    Eigen::Vector3d c, d, c_x_d;  // -B's Gauss-map arc (c, d) and c x d
    Eigen::Vector3d q, v;         // the edge: q + r v, r in [0, 1]
  };
  std::vector<EdgeInA> b_edges;
};

// A and B at poses T_WA, T_WB. Meant for overlapping polytopes (for separated ones the result
// is a separating axis, not the distance).
Penetration polytope_penetration(const ConvexPolytope& A, const Eigen::Isometry3d& T_WA,
                                 const ConvexPolytope& B, const Eigen::Isometry3d& T_WB,
                                 PenetrationScratch& scratch);

}  // namespace stanceplan
