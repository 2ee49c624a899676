#include "render/scene/contact_overlays.h"

#include <algorithm>
#include <cmath>

#include "planner/model/kinematics.h"
#include "render/scene/mesh_library.h"

namespace stanceplan::render {
namespace {

constexpr double kDecalLift = 0.002;       // contact patches float this far off the surface
constexpr double kGroundTolerance = 0.01;  // a contact point this close to the ground is on it

constexpr int kPointDiscSides = 24;
constexpr double kPointDiscMinRadius = 0.004;  // m: a sharp tip's disc stays visible

struct WorldPolygon {
  std::vector<Eigen::Vector3d> vertices;
  Eigen::Vector3d normal;               // outward normal of s1 (points into s2)
  std::vector<Eigen::Vector3d> points;  // where the forces act: the vertices, or a point's one
};

// A point surface (a sphere of radius r at c) touches s2's plane at c - r z2: drawn as a disc of
// radius r (at least kPointDiscMinRadius) there, facing into s2 like a polygon s1.
WorldPolygon point_disc(const Scene& scene, const SystemPose& pose, const Contact& contact) {
  const Surface& s1 = scene.surfaces.get(contact.s1);
  const Surface& s2 = scene.surfaces.get(contact.s2);
  const Eigen::Vector3d c = pose.T_WL(contact.s1.entity, s1.link) * s1.center_L();
  const Eigen::Isometry3d T_WS2 = pose.T_WL(contact.s2.entity, s2.link) * s2.T_LS;
  const Eigen::Vector3d z2 = T_WS2.linear().col(2);
  WorldPolygon out;
  out.normal = -z2;
  out.points = {c - s1.radius * z2};
  // (u, v, -z2) right-handed: increasing angles turn counter-clockwise about s1's normal -z2.
  const Eigen::Vector3d u = T_WS2.linear().col(0), v = out.normal.cross(u);
  const double radius = std::max(s1.radius, kPointDiscMinRadius);
  for (int k = 0; k < kPointDiscSides; ++k) {
    const double angle = 2.0 * M_PI * k / kPointDiscSides;
    out.vertices.push_back(out.points[0] + radius * (std::cos(angle) * u + std::sin(angle) * v));
  }
  return out;
}

WorldPolygon s1_polygon(const Scene& scene, const SystemPose& pose, const Contact& contact) {
  const Surface& s1 = scene.surfaces.get(contact.s1);
  if (s1.is_point()) return point_disc(scene, pose, contact);
  const Eigen::Isometry3d& T_WL = pose.T_WL(contact.s1.entity, s1.link);
  WorldPolygon out;
  for (const Eigen::Vector3d& p_L : s1.vertices_L()) out.vertices.push_back(T_WL * p_L);
  out.normal = T_WL.linear() * s1.normal_L();
  out.points = out.vertices;
  return out;
}

std::vector<Eigen::Vector3f> lifted(const WorldPolygon& polygon, double lift) {
  std::vector<Eigen::Vector3f> out;
  for (const Eigen::Vector3d& p : polygon.vertices)
    out.push_back((p - lift * polygon.normal).cast<float>());
  return out;
}

DrawItem transient_item(DrawList& list, MeshData mesh, Color color, Layer layer) {
  DrawItem item;
  item.mesh = list.keep(std::move(mesh));
  item.transient = true;
  item.color = color;
  item.layer = layer;
  item.casts_shadow = false;
  return item;
}

// The s1 polygon in the contact's colour with a ring around it, both lifted off s2 towards s1's
// body: the ring stays visible around a foot that hides its own sole.
void add_patch(const WorldPolygon& polygon, Color color, const RenderStyle& style, DrawList& list) {
  const std::vector<Eigen::Vector3f> vertices = lifted(polygon, kDecalLift);
  // The vertices turn counter-clockwise about s1's outward normal.
  const Eigen::Vector3f n = polygon.normal.cast<float>();
  DrawItem fill = transient_item(list, render::polygon(vertices, n), color, Layer::Decal);
  fill.frames_view = true;
  list.items.push_back(fill);
  list.items.push_back(
      transient_item(list, polygon_ring(vertices, n, static_cast<float>(style.contact_ring_width)),
                     color, Layer::Decal));
}

// A shaft (cylinder) and a head (cone) from `start` along `vector`.
void add_arrow(const Eigen::Vector3d& start, const Eigen::Vector3d& vector, double radius,
               Color color, DrawList& list) {
  const double length = vector.norm();
  if (length < 1e-6) return;
  const Eigen::Vector3d direction = vector / length;
  const double head = std::min(0.4 * length, 7.0 * radius);
  const double shaft = length - head;
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = rotation_z_to(direction);
  DrawItem item;
  item.color = color;
  item.xray = true;
  item.casts_shadow = true;
  if (shaft > 0.0) {
    T.translation() = start + 0.5 * shaft * direction;
    item.mesh = &MeshLibrary::primitive(ShapeType::Cylinder);
    item.T_WM = scaled_transform(T, Eigen::Vector3d(radius, radius, shaft));
    list.items.push_back(item);
  }
  T.translation() = start + shaft * direction;
  item.mesh = &MeshLibrary::cone();
  item.T_WM = scaled_transform(T, Eigen::Vector3d(2.5 * radius, 2.5 * radius, head));
  list.items.push_back(item);
}

// A cone of half-angle atan(mu) with its apex at the vertex, opening along s2's normal.
void add_friction_cone(const Eigen::Vector3d& apex, const Eigen::Vector3d& axis,
                       const RenderStyle& style, DrawList& list) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = rotation_z_to(-axis);
  T.translation() = apex + style.cone_height * axis;
  DrawItem item;
  item.mesh = &MeshLibrary::cone();
  item.T_WM =
      scaled_transform(T, Eigen::Vector3d(style.cone_height * style.friction,
                                          style.cone_height * style.friction, style.cone_height));
  item.color = style.cone_color;
  item.layer = Layer::Translucent;
  item.casts_shadow = false;
  list.items.push_back(item);
}

void add_center_of_mass(const Eigen::Vector3d& c, const RenderStyle& style, DrawList& list) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = c;
  DrawItem sphere;
  sphere.mesh = &MeshLibrary::primitive(ShapeType::Sphere);
  sphere.T_WM = scaled_transform(T, Eigen::Vector3d::Constant(style.com_radius));
  sphere.color = style.com_color;
  sphere.xray = true;
  sphere.xray_opacity = 0.85f;  // the centre of mass is always inside the body: keep it clear
  list.items.push_back(sphere);
  // Its vertical projection: a thin plumb line and a disc on the ground.
  const Eigen::Vector3d ground(c.x(), c.y(), list.ground.z);
  const double height = c.z() - list.ground.z;
  if (height <= 0.0) return;
  DrawItem line = sphere;
  T.translation() = 0.5 * (c + ground);
  line.mesh = &MeshLibrary::primitive(ShapeType::Cylinder);
  line.T_WM = scaled_transform(
      T, Eigen::Vector3d(0.12 * style.com_radius, 0.12 * style.com_radius, height));
  line.color = style.com_color;
  line.xray_opacity = 0.5f;
  line.casts_shadow = false;
  list.items.push_back(line);
  DrawItem disc = sphere;
  T.translation() = ground + Eigen::Vector3d(0, 0, kDecalLift);
  disc.T_WM =
      scaled_transform(T, Eigen::Vector3d(0.8 * style.com_radius, 0.8 * style.com_radius, 0.002));
  disc.mesh = &MeshLibrary::primitive(ShapeType::Cylinder);
  disc.casts_shadow = false;
  list.items.push_back(disc);
}

void add_support_polygon(const std::vector<Eigen::Vector2d>& points, const RenderStyle& style,
                         DrawList& list) {
  const std::vector<Eigen::Vector2d> hull = convex_hull_2d(points);
  if (hull.size() < 3) return;
  std::vector<Eigen::Vector3f> vertices;
  for (const Eigen::Vector2d& p : hull)
    vertices.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()),
                          static_cast<float>(list.ground.z + 0.5 * kDecalLift));
  const Eigen::Vector3f up = Eigen::Vector3f::UnitZ();
  list.items.push_back(
      transient_item(list, polygon(vertices, up), style.support_color, Layer::Translucent));
  list.items.push_back(transient_item(list, polygon_ring(vertices, up, 0.005f),
                                      with_alpha(style.support_color, 0.8f), Layer::Translucent));
}

}  // namespace

double force_scale(const RenderStyle& style, const std::vector<VertexForce>& forces) {
  if (style.force_scale > 0.0) return style.force_scale;
  double largest = 0.0;
  for (const VertexForce& f : forces) largest = std::max(largest, f.force_W.norm());
  return largest > 0.0 ? style.force_max_length / largest : 0.0;
}

void add_contact_overlays(const Scene& scene, const SystemPose& pose,
                          const std::vector<PlanContact>& contacts,
                          const std::vector<VertexForce>& forces, const RenderStyle& style,
                          DrawList& list) {
  std::vector<Eigen::Vector2d> ground_points;
  for (const PlanContact& pc : contacts) {
    const WorldPolygon polygon = s1_polygon(scene, pose, pc.contact);
    if (style.contacts)
      add_patch(polygon, pc.loaded ? style.loaded_contact : style.unloaded_contact, style, list);
    if (!pc.loaded) continue;
    for (const Eigen::Vector3d& p : polygon.points) {
      if (style.friction_cones && !pc.contact.bilateral)
        add_friction_cone(p, -polygon.normal, style, list);
      // A vertex on the ground, of a surface facing down onto it, supports the robot.
      if (std::abs(p.z() - list.ground.z) < kGroundTolerance && polygon.normal.z() < -0.9)
        ground_points.emplace_back(p.x(), p.y());
    }
  }
  if (style.forces) {
    const double scale = force_scale(style, forces);
    for (const VertexForce& f : forces)
      add_arrow(f.point_W, scale * f.force_W, style.force_radius, style.force_color, list);
  }
  if (style.support_polygon) add_support_polygon(ground_points, style, list);
  if (style.center_of_mass) {
    for (int e = 0; e < scene.system.num_entities(); ++e) {
      const Entity& entity = scene.system.entity(e);
      if (entity.kind != EntityKind::FloatingRobot || entity.model->total_mass <= 0.0) continue;
      add_center_of_mass(center_of_mass(entity, pose.data(e)), style, list);
    }
  }
}

std::vector<Eigen::Vector2d> convex_hull_2d(std::vector<Eigen::Vector2d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return a.x() != b.x() ? a.x() < b.x() : a.y() < b.y();
  });
  const auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a,
                        const Eigen::Vector2d& b) {
    return (a.x() - o.x()) * (b.y() - o.y()) - (a.y() - o.y()) * (b.x() - o.x());
  };
  // Andrew's monotone chain: lower hull, then upper hull.
  std::vector<Eigen::Vector2d> hull(2 * points.size());
  size_t k = 0;
  for (size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], points[i]) <= 1e-12) --k;
    hull[k++] = points[i];
  }
  for (size_t i = points.size(), lower = k + 1; i-- > 1;) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], points[i - 1]) <= 1e-12) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

}  // namespace stanceplan::render
