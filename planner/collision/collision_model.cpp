#include "planner/collision/collision_model.h"

#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/geometry/shape/cylinder.h>
#include <fcl/geometry/shape/sphere.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

#include "planner/collision/srdf.h"
#include "planner/model/mesh_file.h"
#include "planner/util/input_error.h"

namespace stanceplan {
namespace {

std::shared_ptr<fcl::Convexd> make_convex(const ConvexHull& hull) {
  auto vertices = std::make_shared<std::vector<Eigen::Vector3d>>(hull.vertices);
  auto faces = std::make_shared<std::vector<int>>();
  faces->reserve(4 * hull.triangles.size());
  for (const Eigen::Vector3i& t : hull.triangles) {
    faces->insert(faces->end(), {3, t[0], t[1], t[2]});
  }
  auto convex = std::make_shared<fcl::Convexd>(vertices, static_cast<int>(hull.triangles.size()),
                                               faces, /*throw_if_invalid=*/true);
  convex->computeLocalAABB();
  return convex;
}

// Prism with `sides` faces around the z axis whose side faces are tangent to the cylinder.
ConvexHull circumscribed_prism(double radius, double length, int sides,
                               const ConvexHullOptions& options) {
  const double kPi = 3.14159265358979323846;
  const double vertex_radius = radius / std::cos(kPi / sides);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < sides; ++k) {
    const double angle = 2.0 * kPi * k / sides;
    for (double z : {-0.5 * length, 0.5 * length}) {
      points.emplace_back(vertex_radius * std::cos(angle), vertex_radius * std::sin(angle), z);
    }
  }
  return convex_hull(points, options);
}

// For every link, the first link of the rigid body it belongs to (links joined by fixed joints only
// form one body). Links are in topological order, so the parent's body is already known.
std::vector<int> rigid_bodies(const Model& model) {
  std::vector<int> body(model.links.size());
  for (int l = 0; l < model.num_links(); ++l) {
    const Link& link = model.links[l];
    const bool fixed = link.parent_joint >= 0 && !model.joints[link.parent_joint].movable();
    body[l] = fixed ? body[link.parent_link] : l;
  }
  return body;
}

// True when the two links can never come closer or separate through one of their own joints:
// same rigid body, or rigid bodies joined by a single movable joint.
bool joined(const Model& model, const std::vector<int>& body, int a, int b) {
  const int body_a = body[a], body_b = body[b];
  if (body_a == body_b) return true;
  auto parent_body = [&](int root) {
    const int parent = model.links[root].parent_link;
    return parent < 0 ? -1 : body[parent];
  };
  return parent_body(body_a) == body_b || parent_body(body_b) == body_a;
}

void add_bounding_sphere(const std::vector<CollisionShape>& shapes, CollisionLink* link) {
  Eigen::Vector3d center = Eigen::Vector3d::Zero();
  for (int s = link->first_shape; s < link->first_shape + link->num_shapes; ++s) {
    center += shapes[s].T_LG * shapes[s].geometry->aabb_center;
  }
  center /= link->num_shapes;
  double radius = 0.0;
  for (int s = link->first_shape; s < link->first_shape + link->num_shapes; ++s) {
    const Eigen::Vector3d c_L = shapes[s].T_LG * shapes[s].geometry->aabb_center;
    radius = std::max(radius,
                      (c_L - center).norm() + shapes[s].geometry->aabb_radius + shapes[s].margin);
  }
  link->center_L = center;
  link->radius = radius;
}

void add_bounding_box(const std::vector<CollisionShape>& shapes, CollisionLink* link) {
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(INFINITY), hi = -lo;
  for (int s = link->first_shape; s < link->first_shape + link->num_shapes; ++s) {
    const CollisionShape& shape = shapes[s];
    const Eigen::Vector3d grow = Eigen::Vector3d::Constant(shape.margin);
    const auto add = [&](const Eigen::Vector3d& p_G) {
      const Eigen::Vector3d p_L = shape.T_LG * p_G;
      lo = lo.cwiseMin(p_L - grow);
      hi = hi.cwiseMax(p_L + grow);
    };
    if (shape.point_core) {
      add(Eigen::Vector3d::Zero());
    } else {  // every other core is a polytope (CollisionShape)
      for (const Eigen::Vector3d& v_G : shape.polytope->vertices) add(v_G);
    }
  }
  link->box_center_L = 0.5 * (lo + hi);
  link->box_half_L = 0.5 * (hi - lo);
}

}  // namespace

MeshHull HullCache::get(const std::string& mesh_path, const Eigen::Vector3d& scale,
                        const ConvexHullOptions& options) {
  const auto key =
      std::make_pair(mesh_path, std::array<double, 3>{scale.x(), scale.y(), scale.z()});
  std::lock_guard<std::mutex> lock(mutex_);
  auto found = hulls_.find(key);
  if (found != hulls_.end()) return found->second;
  const TriangleMesh mesh = load_mesh(mesh_path, scale);
  require_finite_vertices(mesh, mesh_path);
  MeshHull entry;
  try {
    entry.hull = std::make_shared<const ConvexHull>(convex_hull(mesh.vertices, options));
    entry.convex = make_convex(*entry.hull);
    entry.polytope = std::make_shared<const ConvexPolytope>(polytope_from_hull(*entry.hull));
  } catch (const std::exception& e) {
    throw InputError("mesh file \"" + mesh_path + "\": " + e.what());
  }
  hulls_.emplace(key, entry);
  return entry;
}

size_t HullCache::size() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return hulls_.size();
}

namespace {

CollisionShape make_shape(const Entity& entity, const Link& link, const LinkGeometry& g,
                          const CollisionOptions& options, HullCache& cache) {
  CollisionShape shape;
  shape.type = g.shape.type;
  shape.T_LG = g.T_LG;
  const Eigen::Vector3d& size = g.shape.size;
  switch (g.shape.type) {
    case ShapeType::Box:
      shape.geometry = std::make_shared<fcl::Boxd>(size.x(), size.y(), size.z());
      shape.polytope = std::make_shared<const ConvexPolytope>(polytope_from_box(size));
      shape.geometry->computeLocalAABB();
      break;
    case ShapeType::Cylinder: {
      const int sides = std::max(options.cylinder_sides, 3);
      ConvexHullOptions exact = options.hull;
      exact.simplify_tolerance = 0.0;  // the prism is the simplification
      shape.hull =
          std::make_shared<const ConvexHull>(circumscribed_prism(size.x(), size.y(), sides, exact));
      shape.geometry = make_convex(*shape.hull);
      shape.polytope = std::make_shared<const ConvexPolytope>(polytope_from_hull(*shape.hull));
      break;
    }
    case ShapeType::Sphere:
      shape.geometry = std::make_shared<fcl::Sphered>(0.0);
      shape.geometry->computeLocalAABB();
      shape.point_core = true;
      shape.margin = size.x();
      break;
    case ShapeType::Mesh: {
      if (g.shape.mesh_path.empty()) {
        throw InputError("entity \"" + entity.name + "\", link \"" + link.name +
                         "\": collision mesh \"" + g.shape.mesh_uri + "\" was not resolved");
      }
      const MeshHull mesh = cache.get(g.shape.mesh_path, g.shape.mesh_scale, options.hull);
      shape.geometry = mesh.convex;
      shape.hull = mesh.hull;
      shape.polytope = mesh.polytope;
      shape.margin = mesh.hull->max_outside_distance;  // grown to contain the whole mesh
      break;
    }
  }
  return shape;
}

}  // namespace

CollisionModel::CollisionModel(const System& system, const CollisionOptions& options,
                               HullCache* cache) {
  HullCache local_cache;
  HullCache& hulls = cache != nullptr ? *cache : local_cache;
  for (int e = 0; e < system.num_entities(); ++e) {
    add_entity_shapes(system, e, options, hulls);
  }
  build_pairs(system, options, hulls);
}

void CollisionModel::add_entity_shapes(const System& system, int e, const CollisionOptions& options,
                                       HullCache& cache) {
  const Entity& entity = system.entity(e);
  const Model& model = *entity.model;
  const std::vector<int> body = rigid_bodies(model);
  first_link_.push_back(static_cast<int>(link_of_.size()));
  for (int l = 0; l < model.num_links(); ++l) {
    const Link& link = model.links[l];
    if (link.collisions.empty()) {
      link_of_.push_back(-1);
      continue;
    }
    link_of_.push_back(static_cast<int>(links_.size()));
    CollisionLink collision_link;
    collision_link.entity = e;
    collision_link.link = l;
    collision_link.first_shape = static_cast<int>(shapes_.size());
    collision_link.num_shapes = static_cast<int>(link.collisions.size());
    collision_link.moves = entity.kind == EntityKind::Environment ? false
                           : entity.floating()                    ? true
                                                                  : body[l] != body[0];
    for (const LinkGeometry& g : link.collisions) {
      shapes_.push_back(make_shape(entity, link, g, options, cache));
    }
    add_bounding_sphere(shapes_, &collision_link);
    add_bounding_box(shapes_, &collision_link);
    links_.push_back(collision_link);
  }
}

void CollisionModel::build_pairs(const System& system, const CollisionOptions& options,
                                 HullCache& cache) {
  const int n = static_cast<int>(links_.size());
  // Per link pair: 0 = not disabled, k > 0 = disabled, reason disabled_reasons[k - 1].
  std::vector<int> disabled(static_cast<size_t>(n) * n, 0);
  std::vector<std::string> disabled_reasons;
  std::vector<bool> srdf_disables(system.num_entities(), false);  // some pair of its own links
  auto mark = [&](int a, int b, const std::string& reason) {
    if (a < 0 || b < 0) return;
    disabled_reasons.push_back(reason);
    const int k = static_cast<int>(disabled_reasons.size());
    disabled[static_cast<size_t>(a) * n + b] = k;
    disabled[static_cast<size_t>(b) * n + a] = k;
  };
  for (const auto& [entity_name, srdf_path] : options.srdf_files) {
    const int e = system.find_entity(entity_name);
    if (e < 0) {
      throw InputError(srdf_path + ": SRDF given for entity \"" + entity_name +
                       "\", which the system does not have");
    }
    const Model& model = *system.entity(e).model;
    for (const DisabledCollision& d : load_srdf_disabled_collisions(srdf_path)) {
      const int l1 = model.find_link(d.link1), l2 = model.find_link(d.link2);
      num_unknown_srdf_links_ += (l1 < 0) + (l2 < 0);
      if (l1 >= 0 && l2 >= 0) {
        srdf_disables[e] = true;
        mark(find_link(e, l1), find_link(e, l2),
             "SRDF" + (d.reason.empty() ? std::string() : " (" + d.reason + ")"));
      }
    }
  }
  if (options.computed_matrix) {
    compute_matrices(system, *options.computed_matrix, srdf_disables, cache, mark);
  }
  auto resolve = [&](const LinkName& name) {
    const int e = system.find_entity(name.entity);
    if (e < 0) {
      throw InputError("disabled collision pair: unknown entity \"" + name.entity + "\"");
    }
    const int l = system.entity(e).model->find_link(name.link);
    if (l < 0) {
      throw InputError("disabled collision pair: entity \"" + name.entity + "\" has no link \"" +
                       name.link + "\"");
    }
    return find_link(e, l);
  };
  // After the SRDF files: an explicitly disabled pair reports that reason.
  for (const auto& [first, second] : options.disabled_pairs) {
    mark(resolve(first), resolve(second), "disabled");
  }

  std::vector<std::vector<int>> bodies;
  for (const Entity& entity : system.entities()) bodies.push_back(rigid_bodies(*entity.model));
  pair_of_.assign(static_cast<size_t>(n) * n, -1);
  for (int a = 0; a < n; ++a) {
    for (int b = a + 1; b < n; ++b) {
      const CollisionLink& la = links_[a];
      const CollisionLink& lb = links_[b];
      std::string reason;
      if (la.entity == lb.entity) {
        const Model& model = *system.entity(la.entity).model;
        const std::vector<int>& body = bodies[la.entity];
        if (model.adjacent(la.link, lb.link)) continue;  // joined by a joint: not even listed
        if (body[la.link] == body[lb.link]) {
          reason = "rigidly connected";
        } else if (joined(model, body, la.link, lb.link)) {
          reason = "adjacent bodies";
        }
      }
      if (reason.empty() && !la.moves && !lb.moves) reason = "static";  // constant distance
      const int k = disabled[static_cast<size_t>(a) * n + b];
      if (reason.empty() && k > 0) {
        reason = disabled_reasons[k - 1];
        num_srdf_disabled_ += reason.starts_with("SRDF");
        num_computed_disabled_ += reason.starts_with("computed");
      }
      if (!reason.empty()) {
        excluded_.push_back({la.entity, la.link, lb.entity, lb.link, reason});
        continue;
      }
      pair_of_[static_cast<size_t>(a) * n + b] = static_cast<int>(pairs_.size());
      pair_of_[static_cast<size_t>(b) * n + a] = static_cast<int>(pairs_.size());
      pairs_.push_back({a, b});
    }
  }
}

// Robots that ship no usable SRDF get the matrix MoveIt's setup assistant would have written; its
// adjacent pairs are excluded by build_pairs' own rules anyway.
void CollisionModel::compute_matrices(
    const System& system, const CollisionMatrixOptions& options,
    const std::vector<bool>& srdf_disables, HullCache& cache,
    const std::function<void(int, int, const std::string&)>& mark) {
  for (int e = 0; e < system.num_entities(); ++e) {
    const Entity& entity = system.entity(e);
    if (entity.kind == EntityKind::Environment || srdf_disables[e]) continue;
    computed_matrices_.push_back({e, compute_collision_matrix(entity.model, options, &cache)});
    for (const MatrixPair& p : computed_matrices_.back().matrix.pairs) {
      if (p.reason == DisabledReason::Adjacent) continue;
      mark(find_link(e, p.link_a), find_link(e, p.link_b),
           std::string("computed (") + to_string(p.reason) + ")");
    }
  }
}

int CollisionModel::find_link(int entity, int link) const {
  if (entity < 0 || entity >= num_entities()) return -1;
  const int end =
      entity + 1 < num_entities() ? first_link_[entity + 1] : static_cast<int>(link_of_.size());
  const int index = first_link_[entity] + link;
  if (link < 0 || index >= end) return -1;
  return link_of_[index];
}

int CollisionModel::find_pair(int entity_a, int link_a, int entity_b, int link_b) const {
  const int a = find_link(entity_a, link_a), b = find_link(entity_b, link_b);
  if (a < 0 || b < 0) return -1;
  return pair_of_[static_cast<size_t>(a) * links_.size() + b];
}

CollisionData::CollisionData(const System& system, const CollisionModel& model)
    : T_WG(model.shapes().size(), Eigen::Isometry3d::Identity()) {
  int max_nq = 0;
  for (const Entity& entity : system.entities()) max_nq = std::max(max_nq, entity.nq());
  J_scratch.setZero(3, max_nq);
  size_t max_edges = 0;
  for (const CollisionShape& shape : model.shapes()) {
    if (shape.polytope) max_edges = std::max(max_edges, shape.polytope->edges.size());
  }
  penetration.b_edges.reserve(max_edges);
}

void CollisionData::update(const CollisionModel& model, std::span<const ModelData> data) {
  const std::vector<CollisionShape>& shapes = model.shapes();
  for (const CollisionLink& link : model.links()) {
    const Eigen::Isometry3d& T_WL = data[link.entity].T_WL[link.link];
    for (int s = link.first_shape; s < link.first_shape + link.num_shapes; ++s) {
      T_WG[s] = T_WL * shapes[s].T_LG;
    }
  }
}

}  // namespace stanceplan
