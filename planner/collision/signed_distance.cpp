#include "planner/collision/signed_distance.h"

#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <exception>
#include <limits>
#include <utility>

#include "planner/model/kinematics.h"

namespace stanceplan {
namespace {

// Below this witness-point separation the points give no normal direction.
constexpr double kMinWitnessSeparation = 1e-12;

// Distance between two shapes' cores: witness points on each core and the unit normal from A to B,
// with distance = normal . (p_B - p_A).
struct CoreDistance {
  double distance = 0.0;
  Eigen::Vector3d p_A = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_B = Eigen::Vector3d::Zero();
  Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
};

// FCL's GJK distance with nearest points (world frame), unsigned: -1 when the cores overlap, and
// then no EPA runs (see polytope_penetration.h).
CoreDistance gjk_distance(const CollisionShape& A, const Eigen::Isometry3d& T_WA,
                          const CollisionShape& B, const Eigen::Isometry3d& T_WB,
                          const fcl::DistanceRequestd& request) {
  fcl::DistanceResultd result;  // fresh per query: a reused one keeps its old minimum
  fcl::distance(A.geometry.get(), T_WA, B.geometry.get(), T_WB, request, result);
  CoreDistance out;
  out.distance = result.min_distance;
  out.p_A = result.nearest_points[0];
  out.p_B = result.nearest_points[1];
  out.normal = out.p_B - out.p_A;  // not normalised
  return out;
}

// Two polytope cores: GJK when separated; when they overlap or touch (no witness direction), the
// exact separating-axis penetration, which also gives a touching pair its contact normal.
CoreDistance polytope_distance(const CollisionShape& A, const Eigen::Isometry3d& T_WA,
                               const CollisionShape& B, const Eigen::Isometry3d& T_WB,
                               const fcl::DistanceRequestd& request, PenetrationScratch& scratch) {
  CoreDistance out = gjk_distance(A, T_WA, B, T_WB, request);
  const double length = out.normal.norm();
  if (out.distance > 0.0 && length > kMinWitnessSeparation) {
    out.normal /= length;
    return out;
  }
  const Penetration p = polytope_penetration(*A.polytope, T_WA, *B.polytope, T_WB, scratch);
  out.distance = -p.depth;
  out.normal = p.normal_W;
  out.p_A = p.p_A_W;
  out.p_B = p.p_B_W;
  return out;
}

// A point core (at c_W) against polytope core P, as A = P, B = the point. Inside (or on) P the
// signed distance is exact from P's face planes: the largest n.c - support, the witness on P the
// projection of c on that face. Outside, GJK.
CoreDistance point_polytope_distance(const CollisionShape& P, const Eigen::Isometry3d& T_WP,
                                     const CollisionShape& point, const Eigen::Isometry3d& T_WC,
                                     const fcl::DistanceRequestd& request) {
  const Eigen::Vector3d c_W = T_WC.translation();
  const Eigen::Vector3d c_P = T_WP.inverse() * c_W;
  double largest = -std::numeric_limits<double>::infinity();
  Eigen::Vector3d n_P = Eigen::Vector3d::UnitZ();
  for (const ConvexPolytope::Plane& plane : P.polytope->planes) {
    const double value = plane.normal.dot(c_P) - plane.support;
    if (value > largest) {
      largest = value;
      n_P = plane.normal;
    }
  }
  const Eigen::Vector3d face_normal_W = T_WP.linear() * n_P;
  if (largest > 0.0) {
    CoreDistance out = gjk_distance(P, T_WP, point, T_WC, request);
    const Eigen::Vector3d diff = c_W - out.p_A;
    const double length = diff.norm();
    if (out.distance > 0.0 && length > kMinWitnessSeparation) {
      out.p_B = c_W;
      out.normal = diff / length;
      return out;
    }  // else on the surface up to round-off: the face plane answers
  }
  CoreDistance out;
  out.distance = largest;
  out.normal = face_normal_W;
  out.p_A = c_W - largest * face_normal_W;
  out.p_B = c_W;
  return out;
}

CoreDistance core_distance(const CollisionShape& A, const Eigen::Isometry3d& T_WA,
                           const CollisionShape& B, const Eigen::Isometry3d& T_WB,
                           const fcl::DistanceRequestd& request, PenetrationScratch& scratch) {
  if (A.point_core && B.point_core) {
    CoreDistance out;
    out.p_A = T_WA.translation();
    out.p_B = T_WB.translation();
    out.distance = (out.p_B - out.p_A).norm();
    const double length = (out.p_B - out.p_A).norm();
    out.normal =
        length > 0.0 ? Eigen::Vector3d((out.p_B - out.p_A) / length) : Eigen::Vector3d::UnitZ();
    return out;
  }
  if (B.point_core) return point_polytope_distance(A, T_WA, B, T_WB, request);
  if (A.point_core) {
    CoreDistance swapped = point_polytope_distance(B, T_WB, A, T_WA, request);
    std::swap(swapped.p_A, swapped.p_B);
    swapped.normal = -swapped.normal;
    return swapped;
  }
  return polytope_distance(A, T_WA, B, T_WB, request, scratch);
}

// The shapes are their cores grown by their margins: every distance drops by both margins and the
// witness points move onto the grown surfaces along the normal (E20 on the true shapes).
void apply_margins(const CollisionShape& A, const CollisionShape& B, CoreDistance* d) {
  d->distance -= A.margin + B.margin;
  d->p_A += A.margin * d->normal;
  d->p_B -= B.margin * d->normal;
}

// Adds sign * normal^T J(p_W) of `link` to the block of `values` starting at `column`.
void add_point_term(const System& system, std::span<const ModelData> data,
                    const CollisionLink& link, const Eigen::Vector3d& p_W,
                    const Eigen::Vector3d& normal_W, double sign, int column, CollisionData& work,
                    Eigen::Ref<Eigen::RowVectorXd> values) {
  const Entity& entity = system.entity(link.entity);
  const int nq = entity.nq();
  if (nq == 0) return;
  auto J = work.J_scratch.leftCols(nq);
  point_jacobian_world(entity, data[link.entity], link.link, p_W, J);
  values.segment(column, nq).noalias() += sign * (normal_W.transpose() * J);
}

}  // namespace

DistanceResult signed_distance(const CollisionModel& model, CollisionData& data, int pair,
                               const SignedDistanceOptions& options) {
  const CollisionPair& p = model.pairs()[pair];
  const CollisionLink& link_a = model.links()[p.a];
  const CollisionLink& link_b = model.links()[p.b];
  fcl::DistanceRequestd request;
  request.enable_nearest_points = true;
  request.enable_signed_distance = false;  // GJK only: overlaps go to polytope_penetration
  request.gjk_solver_type = fcl::GST_LIBCCD;
  request.distance_tolerance = options.tolerance;

  DistanceResult best;
  best.distance = std::numeric_limits<double>::infinity();
  const std::vector<CollisionShape>& shapes = model.shapes();
  for (int sa = link_a.first_shape; sa < link_a.first_shape + link_a.num_shapes; ++sa) {
    for (int sb = link_b.first_shape; sb < link_b.first_shape + link_b.num_shapes; ++sb) {
      // A pose that is not finite (a configuration with NaN, from a diverging solve) has no
      // distance, and libccd's GJK asserts (aborts the process) on it: no FCL call, NaN out.
      if (!data.T_WG[sa].matrix().allFinite() || !data.T_WG[sb].matrix().allFinite()) {
        best.ok = false;
        best.distance = std::numeric_limits<double>::quiet_NaN();
        return best;
      }
      CoreDistance d;
      try {
        d = core_distance(shapes[sa], data.T_WG[sa], shapes[sb], data.T_WG[sb], request,
                          data.penetration);
      } catch (const std::exception&) {
        best.ok = false;  // FCL throws on configurations it cannot handle
        continue;
      }
      apply_margins(shapes[sa], shapes[sb], &d);
      if (d.distance < best.distance) {
        best.distance = d.distance;
        best.p_A_W = d.p_A;
        best.p_B_W = d.p_B;
        best.normal_W = d.normal;
        best.shape_a = sa;
        best.shape_b = sb;
      }
    }
  }
  return best;
}

namespace {
// Signed distance from the sphere (c_W, r) to `link`'s bounding box at pose T_WL (negative
// inside: minus the sphere's penetration depth into the box), a lower bound of the signed
// distance from the sphere to the link's shapes: a translation that separates the sphere from the
// box separates whatever they contain.
double sphere_box_lower_bound(const CollisionLink& link, const Eigen::Isometry3d& T_WL,
                              const Eigen::Vector3d& c_W, double r) {
  const Eigen::Vector3d c_L = T_WL.linear().transpose() * (c_W - T_WL.translation());
  const Eigen::Vector3d excess = (c_L - link.box_center_L).cwiseAbs() - link.box_half_L;
  const double outside = excess.maxCoeff();
  return (outside > 0.0 ? excess.cwiseMax(0.0).norm() : outside) - r;
}
}  // namespace

double distance_lower_bound(const CollisionModel& model, std::span<const ModelData> data,
                            int pair) {
  const CollisionPair& p = model.pairs()[pair];
  const CollisionLink& a = model.links()[p.a];
  const CollisionLink& b = model.links()[p.b];
  const Eigen::Isometry3d& T_WA = data[a.entity].T_WL[a.link];
  const Eigen::Isometry3d& T_WB = data[b.entity].T_WL[b.link];
  const Eigen::Vector3d c_A_W = T_WA * a.center_L;
  const Eigen::Vector3d c_B_W = T_WB * b.center_L;
  // Each shape set lies in its sphere and in its box: the largest of three lower bounds.
  return std::max({(c_B_W - c_A_W).norm() - a.radius - b.radius,
                   sphere_box_lower_bound(a, T_WA, c_B_W, b.radius),
                   sphere_box_lower_bound(b, T_WB, c_A_W, a.radius)});
}

GradientBlocks gradient_blocks(const System& system, const CollisionModel& model, int pair) {
  const CollisionPair& p = model.pairs()[pair];
  GradientBlocks blocks;
  for (int entity : {model.links()[p.a].entity, model.links()[p.b].entity}) {
    if (system.entity(entity).nq() == 0) continue;
    if (blocks.count == 1 && blocks.entity[0] == entity) continue;
    blocks.entity[blocks.count] = entity;
    blocks.offset[blocks.count] = system.offset(entity);
    blocks.size[blocks.count] = system.entity(entity).nq();
    ++blocks.count;
  }
  return blocks;
}

void signed_distance_gradient_sparse(const System& system, std::span<const ModelData> data,
                                     const CollisionModel& model, int pair,
                                     const DistanceResult& result, CollisionData& work,
                                     Eigen::Ref<Eigen::RowVectorXd> values) {
  const GradientBlocks blocks = gradient_blocks(system, model, pair);
  const CollisionPair& p = model.pairs()[pair];
  const CollisionLink& link_a = model.links()[p.a];
  const CollisionLink& link_b = model.links()[p.b];
  values.setZero();
  auto column = [&](int entity) { return blocks.entity[0] == entity ? 0 : blocks.size[0]; };
  // E48: d distance / dq = n^T (J_B(p_B) - J_A(p_A)).
  add_point_term(system, data, link_a, result.p_A_W, result.normal_W, -1.0, column(link_a.entity),
                 work, values);
  add_point_term(system, data, link_b, result.p_B_W, result.normal_W, 1.0, column(link_b.entity),
                 work, values);
}

void signed_distance_gradient(const System& system, std::span<const ModelData> data,
                              const CollisionModel& model, int pair, const DistanceResult& result,
                              CollisionData& work, Eigen::Ref<Eigen::RowVectorXd> row) {
  const CollisionPair& p = model.pairs()[pair];
  const CollisionLink& link_a = model.links()[p.a];
  const CollisionLink& link_b = model.links()[p.b];
  row.setZero();
  // E48, each term placed at its entity's offset in q.
  add_point_term(system, data, link_a, result.p_A_W, result.normal_W, -1.0,
                 system.offset(link_a.entity), work, row);
  add_point_term(system, data, link_b, result.p_B_W, result.normal_W, 1.0,
                 system.offset(link_b.entity), work, row);
}

}  // namespace stanceplan
