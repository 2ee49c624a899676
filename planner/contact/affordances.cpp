#include "planner/contact/affordances.h"

#include <algorithm>
#include <cmath>
#include <tuple>

#include "planner/contact/convex_partition.h"
#include "planner/contact/planar_regions.h"
#include "planner/model/mesh_file.h"

namespace stanceplan {
namespace {

// Boundary vertices closer than this to the line of their neighbours are dropped (m): tessellated
// edges become straight and pieces strictly convex, as make_surface requires.
constexpr double kStraightTolerance = 1e-4;

struct Triangles {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;

  int add(const Eigen::Vector3d& p) {
    vertices.push_back(p);
    return static_cast<int>(vertices.size()) - 1;
  }
};

// The 12 triangles of a box, counter-clockwise seen from outside, in the link frame.
void add_box(const LinkGeometry& g, Triangles* out) {
  const Eigen::Vector3d half = 0.5 * g.shape.size;
  const int first = static_cast<int>(out->vertices.size());
  for (int i = 0; i < 8; ++i)  // corner i: bit k set = +half[k]
    out->add(g.T_LG * Eigen::Vector3d((i & 1) ? half.x() : -half.x(),
                                      (i & 2) ? half.y() : -half.y(),
                                      (i & 4) ? half.z() : -half.z()));
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = 1 << ((axis + 1) % 3), v = 1 << ((axis + 2) % 3), a = side ? 1 << axis : 0;
      // (u, v, +axis) is right-handed: (-,-) (+,-) (+,+) (-,+) is counter-clockwise about +axis.
      int quad[4] = {a, a | u, a | u | v, a | v};
      if (!side) std::swap(quad[1], quad[3]);
      out->triangles.emplace_back(first + quad[0], first + quad[1], first + quad[2]);
      out->triangles.emplace_back(first + quad[0], first + quad[2], first + quad[3]);
    }
}

// The two caps of a cylinder (along the geometry's z) as fans of the inscribed regular polygon:
// inside the true cap, so a contact on them is on the cylinder. The curved side gives no surface.
void add_cylinder_caps(const LinkGeometry& g, int sides, Triangles* out) {
  const double r = g.shape.size[0], h = 0.5 * g.shape.size[1];
  for (const double z : {h, -h}) {
    const int centre = out->add(g.T_LG * Eigen::Vector3d(0, 0, z));
    const int first = static_cast<int>(out->vertices.size());
    for (int i = 0; i < sides; ++i) {
      const double angle = 2.0 * M_PI * i / sides;
      out->add(g.T_LG * Eigen::Vector3d(r * std::cos(angle), r * std::sin(angle), z));
    }
    for (int i = 0; i < sides; ++i) {
      const int a = first + i, b = first + (i + 1) % sides;
      if (z > 0)
        out->triangles.emplace_back(centre, a, b);
      else
        out->triangles.emplace_back(centre, b, a);
    }
  }
}

void add_mesh(const LinkGeometry& g, Triangles* out) {
  const TriangleMesh mesh = load_mesh(g.shape.mesh_path, g.shape.mesh_scale);
  require_finite_vertices(mesh, g.shape.mesh_path);
  const int first = static_cast<int>(out->vertices.size());
  for (const Eigen::Vector3d& p : mesh.vertices) out->add(g.T_LG * p);
  for (const Eigen::Vector3i& t : mesh.triangles)
    out->triangles.push_back(t + Eigen::Vector3i::Constant(first));
}

Triangles link_triangles(const Link& link, int cylinder_sides) {
  Triangles out;
  for (const LinkGeometry& g : link.collisions) {
    if (g.shape.type == ShapeType::Box) add_box(g, &out);
    if (g.shape.type == ShapeType::Cylinder) add_cylinder_caps(g, cylinder_sides, &out);
    if (g.shape.type == ShapeType::Mesh && !g.shape.mesh_path.empty()) add_mesh(g, &out);
  }
  return out;
}

// Link poses in the model's root frame with every joint at zero (an environment has no
// configuration; its fixed joints place its links).
std::vector<Eigen::Isometry3d> zero_pose_links(const Model& model) {
  std::vector<Eigen::Isometry3d> T_BL(model.links.size(), Eigen::Isometry3d::Identity());
  for (int l = 1; l < model.num_links(); ++l) {
    const Link& link = model.links[l];
    if (link.parent_link >= 0 && link.parent_joint >= 0)
      T_BL[l] = T_BL[link.parent_link] * model.joints[link.parent_joint].T_PJ;
  }
  return T_BL;
}

bool classify(const Eigen::Vector3d& n_W, const AffordanceOptions& options, AffordanceClass* kind) {
  const double degrees = 180.0 / M_PI;
  const double from_up = std::acos(std::clamp(n_W.z(), -1.0, 1.0)) * degrees;
  if (from_up <= options.slope) {
    *kind = AffordanceClass::Support;
    return true;
  }
  if (std::abs(from_up - 90.0) <= options.lean) {
    *kind = AffordanceClass::Lean;
    return true;
  }
  return false;
}

// The convex pieces of one region, shrunk and filtered, as unnamed surfaces.
void add_pieces(const PlanarRegion& region, int link, const Model& model,
                const Eigen::Isometry3d& T_WL, AffordanceClass kind,
                const AffordanceOptions& options, std::vector<Affordance>* out) {
  for (const RegionOutline& outline : region.outlines) {
    for (const Polygon2& piece :
         convex_partition(outline.outer, outline.holes, kStraightTolerance)) {
      const Polygon2 shrunk =
          simplify_polygon(inset_convex_polygon(piece, options.inset), kStraightTolerance);
      if (shrunk.size() < 3 || 0.5 * signed_area2(shrunk) < options.min_area) continue;
      std::vector<Eigen::Vector3d> vertices_L;
      for (const Eigen::Vector2d& p : shrunk) vertices_L.push_back(region.point(p));
      Affordance a;
      a.kind = kind;
      std::string error;
      // A piece that is not strictly convex after rounding is a sliver: dropped.
      if (!make_surface("", link, model.links[link].name, vertices_L, region.normal, nullptr,
                        &a.surface, &error, 1e-6))
        continue;
      a.normal_W = T_WL.linear() * region.normal;
      const Eigen::Vector2d c = a.surface.centroid_S();
      a.centroid_W = T_WL * (a.surface.T_LS * Eigen::Vector3d(c.x(), c.y(), 0.0));
      out->push_back(std::move(a));
    }
  }
}

// Supports before leans, then height, x, y in micrometres; stable, so exact ties keep link order.
void sort_and_name(std::vector<Affordance>* affordances) {
  auto key = [](const Affordance& a) {
    auto um = [](double v) { return std::llround(v * 1e6); };
    return std::make_tuple(static_cast<int>(a.kind), um(a.centroid_W.z()), um(a.centroid_W.x()),
                           um(a.centroid_W.y()));
  };
  std::stable_sort(affordances->begin(), affordances->end(),
                   [&](const Affordance& a, const Affordance& b) { return key(a) < key(b); });
  int counts[2] = {0, 0};
  for (Affordance& a : *affordances)
    a.surface.name =
        std::string(to_string(a.kind)) + "_" + std::to_string(counts[static_cast<int>(a.kind)]++);
}

}  // namespace

const char* to_string(AffordanceClass kind) {
  return kind == AffordanceClass::Support ? "support" : "lean";
}

std::vector<Affordance> extract_affordances(const Model& model, const Eigen::Isometry3d& T_WB,
                                            const AffordanceOptions& options) {
  PlanarRegionOptions region_options;
  region_options.angle_tolerance = options.angle_tolerance * M_PI / 180.0;
  region_options.offset_tolerance = options.offset_tolerance;
  const std::vector<Eigen::Isometry3d> T_BL = zero_pose_links(model);
  std::vector<Affordance> out;
  for (int l = 0; l < model.num_links(); ++l) {
    const Triangles triangles = link_triangles(model.links[l], options.cylinder_sides);
    if (triangles.triangles.empty()) continue;
    const Eigen::Isometry3d T_WL = T_WB * T_BL[l];
    for (const PlanarRegion& region :
         find_planar_regions(triangles.vertices, triangles.triangles, region_options)) {
      AffordanceClass kind;
      if (region.area < options.min_area ||
          !classify(T_WL.linear() * region.normal, options, &kind))
        continue;
      add_pieces(region, l, model, T_WL, kind, options, &out);
    }
  }
  sort_and_name(&out);
  return out;
}

std::vector<Surface> extract_surfaces(const Model& model, const Eigen::Isometry3d& T_WB,
                                      const AffordanceOptions& options) {
  std::vector<Surface> out;
  for (Affordance& a : extract_affordances(model, T_WB, options)) out.push_back(a.surface);
  return out;
}

}  // namespace stanceplan
