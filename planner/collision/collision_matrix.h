#pragma once
// A robot's self-collision matrix computed the way MoveIt's setup assistant computes the
// <disable_collisions> of an SRDF, so that published models whose collision shapes overlap at every
// posture, shipped without an SRDF (or with one that disables nothing), can be planned without a
// hand-written ignore list. The link pairs it disables, each with its reason:
//  - Adjacent: pairs the collision model never checks anyway (joined by one joint, rigidly
//    connected, or rigid bodies one movable joint apart: CollisionModel's own rules, not repeated);
//  - Always: in collision (signed distance < 0, the real FCL shapes of collision_model.h) in every
//    one of `samples` configurations drawn uniformly within the joint limits;
//  - Default: in collision at the neutral configuration (every joint at 0 clamped into its limits)
//    and in at least `default_fraction` of the samples (MoveIt disables every pair in collision at
//    its default state; the fraction keeps pairs that the planner can still separate);
//  - Never (opt-in): in collision in none of the samples. MoveIt disables these to save time; it is
//    unsound for the postures no sample came near, so nothing here applies it by default.
// Samples come from std::mt19937_64 seeded with `seed`, turned into doubles by our own bit
// arithmetic (the standard's distributions are implementation-defined): the same model, samples
// and seed give the same matrix on every machine.
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "planner/model/model.h"

namespace stanceplan {

class CollisionData;
class CollisionModel;
class HullCache;
struct ModelData;

enum class DisabledReason { Adjacent, Default, Always, Never };

// "adjacent", "default", "always", "never".
const char* to_string(DisabledReason reason);
// MoveIt's spelling in SRDF files: "Adjacent", "Default", "Always", "Never".
const char* srdf_reason(DisabledReason reason);

struct CollisionMatrixOptions {
  // MoveIt's setup assistant decides "always" from rounds of 200 random states (more than 95 % of
  // them in collision; its command-line collisions_updater defaults to 100 %) and "never" from a
  // sampling density the user sets. A thousand samples of which all collide is stricter than
  // either and takes 31 ms on TALOS.
  int samples = 1000;
  uint64_t seed = 0;
  double default_fraction = 0.95;  // "default" needs at least this share of the samples
  bool include_never = false;
};

// A disabled pair of links with collision geometry.
struct MatrixPair {
  int link_a = -1;  // indices into Model::links, link_a < link_b
  int link_b = -1;
  DisabledReason reason = DisabledReason::Adjacent;
  int collisions = 0;  // samples in collision (Adjacent pairs are not sampled: 0)
};

struct CollisionMatrix {
  std::string robot;  // Model::name
  int samples = 0;
  uint64_t seed = 0;
  std::vector<MatrixPair> pairs;  // ordered by (link_a, link_b)

  int count(DisabledReason reason) const;
  // Pairs disabled by sampling (every reason but Adjacent): those the collision model would check.
  int num_sampled() const {
    return static_cast<int>(pairs.size()) - count(DisabledReason::Adjacent);
  }
};

// Whether the pair (index into model.pairs()) is in collision at the poses in `work`
// (CollisionData::update called with `data`): the sign of signed_distance (signed_distance.h)
// without its penetration depth. The grown shapes overlap exactly when some two cores are closer
// than their margins, which FCL's GJK decides; the depth (an exact separating-axis test, up to a
// millisecond on TALOS's hulls) is not needed here.
bool pair_in_collision(const CollisionModel& model, CollisionData& work,
                       std::span<const ModelData> data, int pair);

// The matrix of one model, its root fixed (self-collision does not depend on the root's pose).
// `cache` (optional) shares mesh hulls with other collision models. Throws InputError on an
// unreadable mesh, std::invalid_argument when options.samples < 1.
CollisionMatrix compute_collision_matrix(const std::shared_ptr<const Model>& model,
                                         const CollisionMatrixOptions& options = {},
                                         HullCache* cache = nullptr);

// The counts, e.g. "21 adjacent, 16 always in collision over 1000 samples, seed 0" (reasons with
// no pair are left out, except adjacent and always).
std::string describe_counts(const CollisionMatrix& matrix);

// An SRDF file: <robot name="..."> with one <disable_collisions link1 link2 reason/> per pair.
std::string collision_matrix_srdf(const Model& model, const CollisionMatrix& matrix);

}  // namespace stanceplan
