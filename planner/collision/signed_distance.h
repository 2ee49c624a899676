#pragma once
// Signed distance between the two links of a candidate pair and its derivative with respect to the
// system configuration q (collision avoidance, docs/METHOD.md section 4: E20 constraint, E48
// gradient). A penetration gives a negative distance (minus the penetration depth) with witness
// points on both surfaces. Shapes are cores grown by margins (collision_model.h). Separated
// polytope cores: FCL's GJK (GST_LIBCCD, nearest points on, signed distance off, so that FCL never
// runs its EPA, which can abort the process). Overlapping or touching polytope cores: the exact
// separating-axis penetration of polytope_penetration.h. A point core (sphere centre): exact from
// the other core's face planes when inside it, GJK otherwise. Two point cores: closed form.
#include <Eigen/Core>
#include <array>
#include <span>

#include "planner/collision/collision_model.h"

namespace stanceplan {

struct DistanceResult {
  double distance = 0.0;  // < 0: penetration depth
  // Witness points in the world: p_A_W on link a of the pair, p_B_W on link b. Separated: the
  // closest points. Penetrating: p_A_W is the point of A deepest inside B and p_B_W that of B
  // deepest inside A, so that distance = normal_W . (p_B_W - p_A_W) in both cases.
  Eigen::Vector3d p_A_W = Eigen::Vector3d::Zero();
  Eigen::Vector3d p_B_W = Eigen::Vector3d::Zero();
  // Unit, from A to B: translating B along it increases the distance at rate 1.
  Eigen::Vector3d normal_W = Eigen::Vector3d::UnitZ();
  int shape_a = -1;  // the shapes (indices into CollisionModel::shapes()) realising the minimum
  int shape_b = -1;
  // False when FCL threw on some shape pair, which was skipped; if it was the only pair, distance
  // stays +infinity. Never seen (millions of random and near-degenerate queries), but check it.
  bool ok = true;
};

struct SignedDistanceOptions {
  // GJK termination tolerance (fcl::DistanceRequest::distance_tolerance, default 1e-6 in FCL). On
  // polytope cores GJK ends on exact features, so this matters little; it would on curved support
  // functions, which this module never gives FCL.
  double tolerance = 1e-9;
};

// Signed distance of candidate pair `pair` (index into model.pairs()) at the poses in `data`
// (CollisionData::update must have been called): the minimum over the two links' shapes. Every
// shape pair gets a fresh fcl::DistanceResult (a reused one keeps its old minimum). A shape pair on
// which FCL throws is skipped and clears `ok`. Allocates only what FCL allocates (`data` holds
// the work buffer of the penetration depth).
DistanceResult signed_distance(const CollisionModel& model, CollisionData& data, int pair,
                               const SignedDistanceOptions& options = {});

// Cheap lower bound of the pair's distance from the links' bounding spheres and link-frame
// bounding boxes (sphere against sphere, each sphere against the other's box; may be negative).
double distance_lower_bound(const CollisionModel& model, std::span<const ModelData> data, int pair);

// Which parts of q a pair's gradient row touches: the configuration segments of the links'
// entities (one block when both links are on the same entity; none for an entity without dofs).
struct GradientBlocks {
  int count = 0;
  std::array<int, 2> entity{-1, -1};
  std::array<int, 2> offset{0, 0};  // first column in q (System::offset)
  std::array<int, 2> size{0, 0};    // Entity::nq()
  int total_size() const { return size[0] + size[1]; }
};
GradientBlocks gradient_blocks(const System& system, const CollisionModel& model, int pair);

// E48: d distance / dq = normal^T (J_B(p_B) - J_A(p_A)), J the point Jacobians of the witness
// points as points fixed to their links (kinematics.h point_jacobian_world). Sparse form: `values`
// (1 x gradient_blocks(...).total_size()) receives the blocks' entries, block 0 then block 1.
// `data` must hold forward kinematics at the q of `result`. Allocates nothing.
void signed_distance_gradient_sparse(const System& system, std::span<const ModelData> data,
                                     const CollisionModel& model, int pair,
                                     const DistanceResult& result, CollisionData& work,
                                     Eigen::Ref<Eigen::RowVectorXd> values);
// Dense form: `row` is 1 x system.nq(); entries outside the blocks are set to zero.
void signed_distance_gradient(const System& system, std::span<const ModelData> data,
                              const CollisionModel& model, int pair, const DistanceResult& result,
                              CollisionData& work, Eigen::Ref<Eigen::RowVectorXd> row);

}  // namespace stanceplan
