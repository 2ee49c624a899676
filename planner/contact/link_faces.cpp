#include "planner/contact/link_faces.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <optional>
#include <sstream>

#include "planner/model/mesh_file.h"
#include "planner/util/input_error.h"

namespace stanceplan {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Four significant digits, round-off shown as 0: for messages.
std::string number(double x) {
  std::ostringstream out;
  out << std::setprecision(4) << (std::abs(x) < 5e-5 ? 0.0 : x);
  return out.str();
}

std::string vector_text(const Eigen::Vector3d& v) {
  return "[" + number(v.x()) + ", " + number(v.y()) + ", " + number(v.z()) + "]";
}

double angle_degrees(const Eigen::Vector3d& unit_a, const Eigen::Vector3d& unit_b) {
  return std::acos(std::clamp(unit_a.dot(unit_b), -1.0, 1.0)) * 180.0 / kPi;
}

// The cap of a cylinder geometry at the end `sign` (+1, -1) of its z axis: the inscribed regular
// polygon, first vertex on the cylinder's +x axis, counter-clockwise about the outward normal.
PlanarFace cylinder_cap(const LinkGeometry& cylinder, double sign) {
  const double radius = cylinder.shape.size[0], half_length = 0.5 * cylinder.shape.size[1];
  PlanarFace face;
  face.normal = cylinder.T_LG.linear() * Eigen::Vector3d(0.0, 0.0, sign);
  for (int k = 0; k < kCylinderCapSides; ++k) {
    const double angle = sign * 2.0 * kPi * k / kCylinderCapSides;
    face.vertices.push_back(cylinder.T_LG * Eigen::Vector3d(radius * std::cos(angle),
                                                            radius * std::sin(angle),
                                                            sign * half_length));
  }
  face.offset = face.normal.dot(face.vertices[0]);
  return face;
}

// The mesh's face nearest `direction_L` (hull_face.h), in the link frame; none when no triangle
// of the mesh lies on its convex hull.
std::optional<PlanarFace> mesh_face(const LinkGeometry& mesh_geometry,
                                    const Eigen::Vector3d& direction_L) {
  const Shape& shape = mesh_geometry.shape;
  if (shape.mesh_path.empty())
    throw InputError("mesh \"" + shape.mesh_uri +
                     "\" of the link's collision geometry is not found");
  TriangleMesh mesh = load_mesh(shape.mesh_path, shape.mesh_scale);
  require_finite_vertices(mesh, shape.mesh_path);
  for (Eigen::Vector3d& v : mesh.vertices) v = mesh_geometry.T_LG * v;
  const std::optional<Eigen::Vector3d> normal =
      nearest_hull_normal(mesh.vertices, mesh.triangles, direction_L, kMeshHullTolerance);
  if (!normal) return std::nullopt;
  PlanarFace face =
      support_face(mesh.vertices, *normal, kMeshFaceFlatness, kFaceCollinearTolerance);
  if (face.vertices.empty()) return std::nullopt;
  return face;
}

// Every flat face of one collision geometry that may be the nearest to `direction_L`: all of a
// box's and a cylinder's, a mesh's nearest one.
std::vector<PlanarFace> flat_faces(const LinkGeometry& geometry,
                                   const Eigen::Vector3d& direction_L) {
  std::vector<PlanarFace> faces;
  switch (geometry.shape.type) {
    case ShapeType::Box:
      for (int axis = 0; axis < 3; ++axis)
        for (double sign : {1.0, -1.0}) faces.push_back(box_face(geometry, axis, sign));
      break;
    case ShapeType::Cylinder:
      for (double sign : {1.0, -1.0}) faces.push_back(cylinder_cap(geometry, sign));
      break;
    case ShapeType::Sphere:
      break;
    case ShapeType::Mesh:
      if (std::optional<PlanarFace> face = mesh_face(geometry, direction_L))
        faces.push_back(std::move(*face));
      break;
  }
  return faces;
}

std::string describe_all(const Link& link) {
  std::string out;
  for (const LinkGeometry& g : link.collisions)
    out += (out.empty() ? "" : ", ") + describe_geometry(g);
  return out;
}

// How far the face reaches along the unit direction: its furthest vertex.
double reach(const PlanarFace& face, const Eigen::Vector3d& unit_direction) {
  double out = -std::numeric_limits<double>::infinity();
  for (const Eigen::Vector3d& v : face.vertices) out = std::max(out, v.dot(unit_direction));
  return out;
}

}  // namespace

PlanarFace box_face(const LinkGeometry& box, int axis, double sign) {
  int a = (axis + 1) % 3, b = (axis + 2) % 3;
  if (sign < 0) std::swap(a, b);
  const Eigen::Vector3d half = 0.5 * box.shape.size;
  PlanarFace face;
  face.normal = box.T_LG.linear() * (sign * Eigen::Vector3d::Unit(axis));
  for (const auto& [sa, sb] : {std::pair{1.0, 1.0}, {-1.0, 1.0}, {-1.0, -1.0}, {1.0, -1.0}}) {
    Eigen::Vector3d p_G = Eigen::Vector3d::Zero();
    p_G[axis] = sign * half[axis];
    p_G[a] = sa * half[a];
    p_G[b] = sb * half[b];
    face.vertices.push_back(box.T_LG * p_G);
  }
  face.offset = face.normal.dot(face.vertices[0]);
  return face;
}

LinkFace nearest_link_face(const Model& model, int link, const Eigen::Vector3d& direction_L,
                           const std::string& direction_label) {
  const Link& l = model.links.at(link);
  if (l.collisions.empty())
    throw InputError("link \"" + l.name + "\" has no collision geometry to take a face from");
  const Eigen::Vector3d d = direction_L.normalized();
  std::vector<LinkFace> faces;
  for (int g = 0; g < static_cast<int>(l.collisions.size()); ++g)
    for (PlanarFace& face : flat_faces(l.collisions[g], d)) faces.push_back({std::move(face), g});
  if (faces.empty())
    throw InputError("link \"" + l.name + "\" has no flat face: its collision geometry is " +
                     describe_all(l));
  double nearest = std::numeric_limits<double>::infinity();
  for (const LinkFace& f : faces) nearest = std::min(nearest, angle_degrees(f.face.normal, d));
  // Of the faces tied for nearest, the one reaching furthest along the direction; the first
  // (file order) of equals.
  const LinkFace* best = nullptr;
  for (const LinkFace& f : faces) {
    if (angle_degrees(f.face.normal, d) > nearest + kLinkFaceTieDegrees) continue;
    if (best == nullptr || reach(f.face, d) > reach(best->face, d) + 1e-9) best = &f;
  }
  const double angle = angle_degrees(best->face.normal, d);
  if (angle > kLinkFaceMaxDegrees)
    throw InputError("link \"" + l.name + "\" has no flat face within " +
                     number(kLinkFaceMaxDegrees) + " degrees of " + direction_label +
                     ": the nearest outward normal is " + vector_text(best->face.normal) + " (" +
                     number(angle) + " degrees away, link frame); its collision geometry is " +
                     describe_all(l));
  return *best;
}

Surface surface_from_link_face(const Model& model, int link, const Eigen::Vector3d& direction_L,
                               const std::string& direction_label, double inset,
                               const Eigen::Vector3d* x_axis_L, const std::string& name) {
  const Link& l = model.links.at(link);
  const LinkFace found = nearest_link_face(model, link, direction_L, direction_label);
  const PlanarFace face = inset_face(found.face, inset, kFaceCollinearTolerance);
  if (face.vertices.empty())
    throw InputError("inset " + number(inset) + " m leaves nothing of face " + direction_label +
                     " of link \"" + l.name + "\" (" +
                     describe_geometry(l.collisions[found.geometry]) + "; the face is " +
                     number(narrowest_width(found.face)) + " m across at its narrowest)");
  Surface surface;
  std::string error;
  if (!make_surface(name, link, l.name, face.vertices, face.normal, x_axis_L, &surface, &error,
                    1e-9))
    throw InputError("face " + direction_label + " of link \"" + l.name + "\": " + error);
  return surface;
}

std::string describe_geometry(const LinkGeometry& geometry) {
  const Eigen::Vector3d& size = geometry.shape.size;
  switch (geometry.shape.type) {
    case ShapeType::Box:
      return "box " + number(size.x()) + " x " + number(size.y()) + " x " + number(size.z()) + " m";
    case ShapeType::Cylinder:
      return "cylinder of radius " + number(size[0]) + " m and length " + number(size[1]) + " m";
    case ShapeType::Sphere:
      return "sphere of radius " + number(size[0]) + " m";
    case ShapeType::Mesh:
      return "mesh " + geometry.shape.mesh_uri;
  }
  return "?";
}

}  // namespace stanceplan
