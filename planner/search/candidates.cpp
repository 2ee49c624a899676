#include "planner/search/candidates.h"

#include <fnmatch.h>
#include <algorithm>
#include <cmath>

namespace stanceplan {
namespace {

std::vector<Eigen::Vector3d> world_vertices(const Scene& scene, const std::vector<ModelData>& data,
                                            SurfaceRef r) {
  const Surface& s = scene.surfaces.get(r);
  std::vector<Eigen::Vector3d> out;
  for (const Eigen::Vector3d& v : s.vertices_L()) out.push_back(data[r.entity].T_WL[s.link] * v);
  return out;
}

double point_segment_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& a,
                              const Eigen::Vector3d& b) {
  const Eigen::Vector3d ab = b - a;
  const double t = std::clamp((p - a).dot(ab) / std::max(ab.squaredNorm(), 1e-18), 0.0, 1.0);
  return (p - (a + t * ab)).norm();
}

// Distance from p to a convex polygon (counter-clockwise about `normal`).
double point_polygon_distance(const Eigen::Vector3d& p, const std::vector<Eigen::Vector3d>& poly,
                              const Eigen::Vector3d& normal) {
  const int n = static_cast<int>(poly.size());
  bool inside = true;
  for (int i = 0; i < n; ++i)
    if ((poly[(i + 1) % n] - poly[i]).cross(p - poly[i]).dot(normal) < 0.0) inside = false;
  if (inside) return std::abs((p - poly[0]).dot(normal));
  double d = INFINITY;
  for (int i = 0; i < n; ++i)
    d = std::min(d, point_segment_distance(p, poly[i], poly[(i + 1) % n]));
  return d;
}

// Least distance from a vertex of either polygon to the other (0 once they touch or cross).
double touching_gap(const std::vector<Eigen::Vector3d>& va, const std::vector<Eigen::Vector3d>& vb,
                    const Eigen::Vector3d& na, const Eigen::Vector3d& nb) {
  double d = INFINITY;
  for (const auto& p : va) d = std::min(d, point_polygon_distance(p, vb, nb));
  for (const auto& p : vb) d = std::min(d, point_polygon_distance(p, va, na));
  return d;
}

// A floating body with mass must keep at least one contact on it (SearchOptions::min_contacts).
bool leaves_a_body_unsupported(const Scene& scene, const Stance& stance, int removed,
                               int min_contacts) {
  const Contact& c = stance.contacts()[removed];
  for (SurfaceRef r : {c.s1, c.s2}) {
    const Entity& e = scene.system.entity(r.entity);
    if (!e.floating() || e.model->total_mass <= 0.0) continue;
    int others = 0;
    for (int i = 0; i < stance.size(); ++i)
      if (i != removed && (stance.contacts()[i].s1.entity == r.entity ||
                           stance.contacts()[i].s2.entity == r.entity))
        ++others;
    if (others < std::max(1, min_contacts)) return true;
  }
  return false;
}

bool matches(const Scene& scene, const Contact& c,
             const std::vector<std::pair<std::string, std::string>>& patterns) {
  const std::string s1 = scene.surfaces.id(scene.system, c.s1),
                    s2 = scene.surfaces.id(scene.system, c.s2);
  for (const auto& [p1, p2] : patterns)
    if ((fnmatch(p1.c_str(), s1.c_str(), 0) == 0 && fnmatch(p2.c_str(), s2.c_str(), 0) == 0) ||
        (fnmatch(p1.c_str(), s2.c_str(), 0) == 0 && fnmatch(p2.c_str(), s1.c_str(), 0) == 0))
      return true;
  return false;
}

bool allowed_pair(const Scene& scene, const Contact& c, const SearchOptions& options) {
  return options.contact_pairs.empty() || matches(scene, c, options.contact_pairs);
}

// A "last" contact waits until every other goal contact is in the stance.
bool allowed_now(const Scene& scene, const Contact& c, const Stance& stance, const Stance& goal,
                 const SearchOptions& options) {
  if (options.last_contacts.empty() || !matches(scene, c, options.last_contacts)) return true;
  for (const Contact& g : goal.contacts())
    if (!matches(scene, g, options.last_contacts) && stance.find(g) < 0) return false;
  return true;
}

// The rigid body a surface's link belongs to: the link itself or its nearest ancestor reached
// through fixed joints; every link that never moves (the environment, a fixed robot's base) is
// one body, the world {-1, -1}.
std::pair<int, int> rigid_body(const Scene& scene, SurfaceRef r) {
  const int link = scene.surfaces.get(r).link;
  if (link_is_static(scene, r.entity, link)) return {-1, -1};
  const Model& model = *scene.system.entity(r.entity).model;
  int l = link;
  while (l > 0 && !model.joints[model.links[l].parent_joint].movable())
    l = model.links[l].parent_link;
  return {r.entity, l};
}

Eigen::Vector3d normal_W(const Scene& scene, const std::vector<ModelData>& data, SurfaceRef r) {
  const Surface& s = scene.surfaces.get(r);
  return data[r.entity].T_WL[s.link].linear() * s.normal_L();
}

double angle_between(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0));
}

// A planar contact turns its s1 normal against its s2 normal. Two contacts between the same two
// rigid bodies B and C therefore fix the angle between their normals on B to the angle between
// their normals on C (each angle is the same at every configuration). A candidate whose angles
// differ from an existing contact's by more than kRigidAngleTolerance can never be realised: a
// side of a rigid cylinder standing on a platform cannot also lie on that platform, nor on the
// floor beneath it (exact, up to the solver's tolerance on the normals).
constexpr double kRigidAngleTolerance = 1e-3;  // rad

bool rigidly_incompatible(const Scene& scene, const std::vector<ModelData>& data, const Contact& c,
                          const Stance& stance) {
  const auto b1 = rigid_body(scene, c.s1), b2 = rigid_body(scene, c.s2);
  // A point contact turns nothing (a sphere on a plane): no rule from it or for it.
  if (scene.surfaces.get(c.s1).is_point()) return false;
  for (const Contact& k : stance.contacts()) {
    if (scene.surfaces.get(k.s1).is_point()) continue;
    const auto k1 = rigid_body(scene, k.s1), k2 = rigid_body(scene, k.s2);
    // The normals of one body paired with those of the other, in the same order on both sides.
    SurfaceRef on_b = k.s1, on_c = k.s2;
    if (b1 == k2 && b2 == k1)
      std::swap(on_b, on_c);
    else if (!(b1 == k1 && b2 == k2))
      continue;
    const double on_first = angle_between(normal_W(scene, data, c.s1), normal_W(scene, data, on_b));
    const double on_second =
        angle_between(normal_W(scene, data, c.s2), normal_W(scene, data, on_c));
    if (std::abs(on_first - on_second) > kRigidAngleTolerance) return true;
  }
  return false;
}

// The generalisation to two links of one robot joined by joints (normal_angle_range.h): contacts
// X-X' and Y-Y' whose X and Y are on different bodies of one entity and whose X' and Y' are on one
// rigid body (the world: floor and treads) need angle(n_X, n_Y) = angle(n_X', n_Y'), which the
// joint limits between X's and Y's links may not allow (exact, up to the same tolerance).
bool normals_cannot_meet(const Scene& scene, const std::vector<ModelData>& data, const Contact& c,
                         const Stance& stance, NormalAngleTable& angles) {
  for (const Contact& k : stance.contacts())
    for (const auto& [x, x_partner] : {std::pair(c.s1, c.s2), std::pair(c.s2, c.s1)})
      for (const auto& [y, y_partner] : {std::pair(k.s1, k.s2), std::pair(k.s2, k.s1)}) {
        if (x.entity != y.entity || rigid_body(scene, x) == rigid_body(scene, y)) continue;
        // A point contact leaves its normal free (no E8).
        if (scene.surfaces.get(x).is_point() || scene.surfaces.get(y).is_point()) continue;
        if (rigid_body(scene, x_partner) != rigid_body(scene, y_partner)) continue;
        const double needed =
            angle_between(normal_W(scene, data, x_partner), normal_W(scene, data, y_partner));
        if (!angles.between(x, y).contains(needed, kRigidAngleTolerance)) return true;
      }
  return false;
}

// RBPRM's reachability condition, made sound (reach_bound.h). In case 1 every contact of the
// stance keeps its placement, so a kept contact y-y' whose partner y' never moves holds y where it
// is at the node. The new contact's surface x must touch its partner x'; when x' never moves
// either, a point of x lies on x''s polygon, and every point of x is within reach(x, y) of every
// point of y: a partner farther than that from y can never be touched, whatever the posture.
constexpr double kReachTolerance = 1e-3;  // m, above the solver's tolerance on E9-E11

bool beyond_reach(const Scene& scene, const std::vector<ModelData>& data, const Contact& c,
                  const Stance& stance, ReachTable& reach) {
  const auto is_static = [&](SurfaceRef r) {
    return link_is_static(scene, r.entity, scene.surfaces.get(r).link);
  };
  for (const auto& [x, x_partner] : {std::pair(c.s1, c.s2), std::pair(c.s2, c.s1)}) {
    if (is_static(x) || !is_static(x_partner)) continue;
    for (const Contact& k : stance.contacts())
      for (const auto& [y, y_partner] : {std::pair(k.s1, k.s2), std::pair(k.s2, k.s1)}) {
        if (y.entity != x.entity || is_static(y) || !is_static(y_partner)) continue;
        if (surface_gap(scene, data, x_partner, y) > reach.between(x, y) + kReachTolerance)
          return true;
      }
  }
  return false;
}

}  // namespace

bool link_is_static(const Scene& scene, int entity, int link) {
  const Entity& e = scene.system.entity(entity);
  if (e.floating()) return false;
  const Model& model = *e.model;
  for (int l = link; l > 0; l = model.links[l].parent_link)
    if (model.joints[model.links[l].parent_joint].movable()) return false;
  return true;
}

double surface_gap(const Scene& scene, const std::vector<ModelData>& data, SurfaceRef a,
                   SurfaceRef b) {
  if (scene.surfaces.get(b).is_point() && !scene.surfaces.get(a).is_point())
    return surface_gap(scene, data, b, a);
  if (scene.surfaces.get(a).is_point())  // a sphere: its centre's distance less its radius
    return point_polygon_distance(world_vertices(scene, data, a)[0], world_vertices(scene, data, b),
                                  normal_W(scene, data, b)) -
           scene.surfaces.get(a).radius;
  return touching_gap(world_vertices(scene, data, a), world_vertices(scene, data, b),
                      normal_W(scene, data, a), normal_W(scene, data, b));
}

SurfaceGaps surface_gaps(const Scene& scene, const std::vector<ModelData>& data, SurfaceRef a,
                         SurfaceRef b) {
  if (scene.surfaces.get(a).is_point() || scene.surfaces.get(b).is_point()) {
    const double gap = surface_gap(scene, data, a, b);  // a sphere's centre is its only point
    return {gap, gap};
  }
  const auto va = world_vertices(scene, data, a), vb = world_vertices(scene, data, b);
  const Eigen::Vector3d nb = normal_W(scene, data, b);
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& v : va) centre += v / double(va.size());
  return {touching_gap(va, vb, normal_W(scene, data, a), nb),
          point_polygon_distance(centre, vb, nb)};
}

std::vector<Candidate> enumerate_candidates(const Scene& scene, const std::vector<ModelData>& data,
                                            const Stance& stance, const Stance& goal,
                                            const SearchOptions& options, NormalAngleTable* angles,
                                            ReachTable* reach) {
  std::vector<Candidate> out;
  // Adj-: remove one contact (case 2).
  for (int i = 0; i < stance.size(); ++i) {
    const Contact& c = stance.contacts()[i];
    if (c.fixed || leaves_a_body_unsupported(scene, stance, i, options.min_contacts)) continue;
    out.push_back({false, c});
  }
  // Adj+: one candidate per pair of surfaces (case 1).
  std::vector<SurfaceRef> all;
  for (int e = 0; e < scene.system.num_entities(); ++e)
    for (int k = 0; k < int(scene.surfaces.of(e).size()); ++k) all.push_back({e, k});
  auto used_as_s1 = [&](SurfaceRef r) {
    return std::any_of(stance.contacts().begin(), stance.contacts().end(),
                       [&](const Contact& c) { return c.s1 == r; });
  };
  for (size_t i = 0; i < all.size(); ++i)
    for (size_t j = i + 1; j < all.size(); ++j) {
      SurfaceRef a = all[i], b = all[j];
      const Surface& sa = scene.surfaces.get(a);
      const Surface& sb = scene.surfaces.get(b);
      if (a.entity == b.entity && sa.link == sb.link) continue;
      if (sa.is_point() && sb.is_point()) continue;  // two spheres touch at no plane
      if (a.entity == b.entity && !options.self_contacts) continue;
      if (link_is_static(scene, a.entity, sa.link) && link_is_static(scene, b.entity, sb.link))
        continue;
      Contact c;
      // s1 is the smaller surface (a point always: area 0, and s1 only), unless the goal states
      // the pair the other way round.
      const bool a_first = sa.is_point() || (!sb.is_point() && sa.area() <= sb.area());
      c.s1 = a_first ? a : b;
      c.s2 = a_first ? b : a;
      const int in_goal = goal.find(c);
      Contact reversed = c;
      std::swap(reversed.s1, reversed.s2);
      const int in_goal_reversed = goal.find(reversed);
      if (in_goal >= 0)
        c = goal.contacts()[in_goal];
      else if (in_goal_reversed >= 0)
        c = goal.contacts()[in_goal_reversed];
      if (stance.find(c) >= 0 || stance.uses_surface(c.s1) || used_as_s1(c.s2)) continue;
      if (!allowed_pair(scene, c, options) || !allowed_now(scene, c, stance, goal, options))
        continue;
      if (rigidly_incompatible(scene, data, c, stance)) continue;
      if (angles != nullptr && normals_cannot_meet(scene, data, c, stance, *angles)) continue;
      if (surface_gap(scene, data, c.s1, c.s2) > options.contact_reach) continue;
      if (reach != nullptr && beyond_reach(scene, data, c, stance, *reach)) continue;
      out.push_back({true, c});
    }
  return out;
}

}  // namespace stanceplan
