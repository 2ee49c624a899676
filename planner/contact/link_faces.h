#pragma once
// Contact surfaces from a link's collision geometry (surface files' `face:`,
// docs/SURFACE_FORMAT.md): the flat face of the geometry whose outward normal is nearest a
// direction of the link frame.
//
// The flat faces of each collision geometry, in the link frame:
//  - a box: its six faces;
//  - a cylinder: its two end caps, each as the regular polygon of kCylinderCapSides sides
//    inscribed in the cap's circle (a vertex on the cylinder frame's +x axis), so never larger
//    than the cap; its side is curved and has no flat face;
//  - a sphere: none;
//  - a mesh: the faces of the convex hull of its vertices that hold one of its triangles
//    (hull_face.h). The face of normal n gathers every vertex within kMeshFaceFlatness of the
//    support plane along n, projected on that plane: coplanar hull triangles, and a face modelled
//    with a slight curvature or noise (TALOS's soles rise 1.9 mm over their 0.2 m), are one face,
//    lying on the outermost plane so that it never cuts into the mesh.
// The face taken is the one whose normal makes the smallest angle with the direction; normals
// within kLinkFaceTieDegrees of that angle tie, and of tied faces the one reaching furthest along
// the direction wins (a sole plate below an ankle block). A face further than kLinkFaceMaxDegrees
// from the direction is refused: the link has no flat face there.
#include <Eigen/Core>
#include <string>

#include "planner/contact/hull_face.h"
#include "planner/contact/surface.h"
#include "planner/model/model.h"

namespace stanceplan {

inline constexpr int kCylinderCapSides = 16;
inline constexpr double kMeshFaceFlatness = 2e-3;        // m
inline constexpr double kFaceCollinearTolerance = 1e-4;  // m, vertices dropped (simplify_polygon)
inline constexpr double kMeshHullTolerance = 1e-5;       // m, a triangle on the hull
inline constexpr double kLinkFaceTieDegrees = 1.0;       // normals this close to equally near tie
inline constexpr double kLinkFaceMaxDegrees = 30.0;      // the farthest a face may be

struct LinkFace {
  PlanarFace face;    // link frame
  int geometry = -1;  // index into the link's collisions
};

// The face of the link's collision geometry nearest `direction_L` (link frame, any length but
// zero). `direction_label` names the direction in messages ("-z", "[0, 0, -1]"). Throws InputError
// when the link has no collision geometry, no flat face, or none within kLinkFaceMaxDegrees (naming
// the nearest normal found and the link's geometry), and when a mesh cannot be read.
LinkFace nearest_link_face(const Model& model, int link, const Eigen::Vector3d& direction_L,
                           const std::string& direction_label);

// That face shrunk by `inset` (m, >= 0) as a surface named `name`: its frame's origin at the
// vertex centroid, z its outward normal, x the given `x_axis_L` projected, or by default the rule
// of make_surface (the first of the link's x, y, z axes not nearly parallel to the normal,
// projected). Throws InputError as nearest_link_face does, and when the inset leaves nothing.
Surface surface_from_link_face(const Model& model, int link, const Eigen::Vector3d& direction_L,
                               const std::string& direction_label, double inset,
                               const Eigen::Vector3d* x_axis_L, const std::string& name);

// The face of a box geometry along its own axis `axis` (0, 1, 2), on the side `sign` (+1, -1), in
// the link frame: vertices (+a, +b), (-a, +b), (-a, -b), (+a, -b) along the box's axes a, b with
// (a, b, sign * axis) right-handed, so counter-clockwise about the outward normal, and
// vertices[0] - vertices[1] along a.
PlanarFace box_face(const LinkGeometry& box, int axis, double sign);

// "box 0.22 x 0.13 x 0.03 m", "cylinder radius 0.03 m, length 0.08 m", "sphere radius 0.05 m",
// "mesh package://robot/meshes/foot.stl": for messages.
std::string describe_geometry(const LinkGeometry& geometry);

}  // namespace stanceplan
