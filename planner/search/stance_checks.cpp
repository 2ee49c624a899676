#include "planner/search/stance_checks.h"

#include <iomanip>
#include <sstream>
#include <utility>

#include "planner/model/kinematics.h"
#include "planner/solver/pinned_pairs.h"
#include "planner/util/input_error.h"

namespace stanceplan {
namespace {

// Deeper than this is a fault of the file (the collision active set's own tolerance).
constexpr double kPenetrationTolerance = 1e-4;

std::string describe(const Problem& problem, const StanceContact& c) {
  const Scene& scene = problem.scene;
  return c.field + " (" + scene.surfaces.id(scene.system, c.contact.s1) + " on " +
         scene.surfaces.id(scene.system, c.contact.s2) + ")";
}

void check_stance(const Problem& problem, const std::vector<StanceContact>& stance) {
  const Scene& scene = problem.scene;
  const PostureRequest request = problem.loaded_request(stance, problem.initial_configuration);
  std::vector<ModelData> data = system_kinematics(scene.system, request.q_init);
  place_pinned_links(scene, request, data);
  const PinnedPairDistance* worst = nullptr;
  const std::vector<PinnedPairDistance> pairs = pinned_pair_distances(scene, request, data);
  for (const PinnedPairDistance& d : pairs)
    if (d.distance < -kPenetrationTolerance && (!worst || d.distance < worst->distance)) worst = &d;
  if (!worst || (worst->contact_a < 0 && worst->contact_b < 0)) return;
  const CollisionPair& pair = scene.collision->pairs()[size_t(worst->pair)];
  std::string a = collision_link_name(scene, pair.a), b = collision_link_name(scene, pair.b);
  const StanceContact* by_a = worst->contact_a >= 0 ? &stance[size_t(worst->contact_a)] : nullptr;
  const StanceContact* by_b = worst->contact_b >= 0 ? &stance[size_t(worst->contact_b)] : nullptr;
  if (!by_a || (by_b && worst->contact_b < worst->contact_a)) {  // in the file's order
    std::swap(a, b);
    std::swap(by_a, by_b);
  }
  std::ostringstream what;
  what << std::fixed << std::setprecision(4);
  if (by_a && by_b)
    what << "the fixed placements of " << describe(problem, *by_a) << " and "
         << describe(problem, *by_b) << " put " << a << " and " << b << " " << -worst->distance
         << " m into each other";
  else
    what << "the fixed placement of " << describe(problem, *by_a) << " puts " << a << " "
         << -worst->distance << " m into " << b;
  const StanceContact& at = by_b ? *by_b : *by_a;  // the later entry, where the fault shows
  throw InputError(problem.file + (at.line > 0 ? ":" + std::to_string(at.line) : "") + ": " +
                   at.field + ": " + what.str());
}

}  // namespace

void check_pinned_stances(const Problem& problem) {
  if (!problem.scene.collision || !problem.solver.enforce_collisions) return;
  check_stance(problem, problem.initial_stance);
  check_stance(problem, problem.goal_stance);
}

}  // namespace stanceplan
