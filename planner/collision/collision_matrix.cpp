#include "planner/collision/collision_matrix.h"

#include <fcl/narrowphase/distance.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <random>
#include <span>
#include <stdexcept>
#include <utility>

#include "planner/collision/collision_model.h"
#include "planner/collision/signed_distance.h"
#include "planner/model/kinematics.h"

namespace stanceplan {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Where each dof is drawn from: its limits, or one turn for a revolute joint without finite limits
// (continuous), or 0 for a prismatic joint without them (a URDF requires them; nothing to sample).
std::vector<std::pair<double, double>> sampling_ranges(const Model& model) {
  std::vector<std::pair<double, double>> ranges;
  for (int k = 0; k < model.num_dofs(); ++k) {
    const Joint& joint = model.joints[model.dof_joints[k]];
    if (joint.has_position_limits && std::isfinite(joint.lower) && std::isfinite(joint.upper)) {
      ranges.emplace_back(joint.lower, joint.upper);
    } else if (joint.type == JointType::Prismatic) {
      ranges.emplace_back(0.0, 0.0);
    } else {
      ranges.emplace_back(-kPi, kPi);
    }
  }
  return ranges;
}

// Uniform in [0, 1) from the top 53 bits: the same on every platform, unlike
// std::uniform_real_distribution, whose algorithm the standard leaves to the library.
double uniform01(std::mt19937_64& random) {
  return static_cast<double>(random() >> 11) * 0x1.0p-53;
}

// What sampling learns of each candidate pair of the model.
struct PairTally {
  bool at_neutral = false;  // in collision at the neutral configuration
  int collisions = 0;       // samples in collision, exact while the pair could still be disabled
};

// Whether a pair's reason can still change: it has collided in every sample so far (always), or it
// collided at the neutral configuration and can still reach the default share, or it has never
// collided and "never" was asked for. The others need no further distance.
bool undecided(const PairTally& tally, int done, int samples, int default_needed,
               bool include_never) {
  if (tally.collisions == done) return true;
  if (tally.at_neutral && tally.collisions + (samples - done) >= default_needed) return true;
  return include_never && tally.collisions == 0;
}

std::vector<PairTally> tally_samples(const Entity& entity, const CollisionModel& collision,
                                     const System& system, const CollisionMatrixOptions& options,
                                     int default_needed) {
  const int num_pairs = static_cast<int>(collision.pairs().size());
  std::vector<PairTally> tallies(num_pairs);
  std::vector<ModelData> data(1, ModelData(entity));
  CollisionData work(system, collision);
  forward_kinematics(entity, system.neutral_configuration(), data[0]);
  work.update(collision, data);
  std::vector<int> active;
  for (int p = 0; p < num_pairs; ++p) {
    tallies[p].at_neutral = pair_in_collision(collision, work, data, p);
    active.push_back(p);
  }
  const std::vector<std::pair<double, double>> ranges = sampling_ranges(*entity.model);
  std::mt19937_64 random(options.seed);
  Eigen::VectorXd q(entity.nq());
  for (int done = 0; done < options.samples && !active.empty(); ++done) {
    for (int k = 0; k < q.size(); ++k) {
      const double u = uniform01(random);  // drawn for every dof, so samples never shift
      q[k] = ranges[k].first + u * (ranges[k].second - ranges[k].first);
    }
    forward_kinematics(entity, q, data[0]);
    work.update(collision, data);
    std::erase_if(active, [&](int p) {
      return !undecided(tallies[p], done, options.samples, default_needed, options.include_never);
    });
    for (int p : active) tallies[p].collisions += pair_in_collision(collision, work, data, p);
  }
  return tallies;
}

// Distance between two shapes' cores: closed form for two points, else FCL's GJK (unsigned, as in
// signed_distance.cpp: no EPA; -1 when the cores overlap).
double core_distance(const CollisionShape& A, const Eigen::Isometry3d& T_WA,
                     const CollisionShape& B, const Eigen::Isometry3d& T_WB,
                     const fcl::DistanceRequestd& request) {
  if (A.point_core && B.point_core) return (T_WB.translation() - T_WA.translation()).norm();
  fcl::DistanceResultd result;
  fcl::distance(A.geometry.get(), T_WA, B.geometry.get(), T_WB, request, result);
  return result.min_distance;
}

}  // namespace

bool pair_in_collision(const CollisionModel& model, CollisionData& work,
                       std::span<const ModelData> data, int pair) {
  if (distance_lower_bound(model, data, pair) > 0.0) return false;
  const CollisionPair& p = model.pairs()[pair];
  const CollisionLink& a = model.links()[p.a];
  const CollisionLink& b = model.links()[p.b];
  fcl::DistanceRequestd request;
  request.enable_nearest_points = false;
  request.enable_signed_distance = false;
  request.gjk_solver_type = fcl::GST_LIBCCD;
  const std::vector<CollisionShape>& shapes = model.shapes();
  for (int sa = a.first_shape; sa < a.first_shape + a.num_shapes; ++sa) {
    for (int sb = b.first_shape; sb < b.first_shape + b.num_shapes; ++sb) {
      const double margins = shapes[sa].margin + shapes[sb].margin;
      try {
        if (core_distance(shapes[sa], work.T_WG[sa], shapes[sb], work.T_WG[sb], request) < margins)
          return true;
      } catch (const std::exception&) {
        continue;  // as signed_distance does: FCL throws on configurations it cannot handle
      }
    }
  }
  return false;
}

const char* to_string(DisabledReason reason) {
  switch (reason) {
    case DisabledReason::Adjacent:
      return "adjacent";
    case DisabledReason::Default:
      return "default";
    case DisabledReason::Always:
      return "always";
    case DisabledReason::Never:
      return "never";
  }
  return "?";
}

const char* srdf_reason(DisabledReason reason) {
  switch (reason) {
    case DisabledReason::Adjacent:
      return "Adjacent";
    case DisabledReason::Default:
      return "Default";
    case DisabledReason::Always:
      return "Always";
    case DisabledReason::Never:
      return "Never";
  }
  return "?";
}

int CollisionMatrix::count(DisabledReason reason) const {
  return static_cast<int>(std::count_if(pairs.begin(), pairs.end(),
                                        [&](const MatrixPair& p) { return p.reason == reason; }));
}

CollisionMatrix compute_collision_matrix(const std::shared_ptr<const Model>& model,
                                         const CollisionMatrixOptions& options, HullCache* cache) {
  if (options.samples < 1) {
    throw std::invalid_argument("compute_collision_matrix: samples must be at least 1, not " +
                                std::to_string(options.samples));
  }
  System system;
  Entity entity;
  entity.name = model->name.empty() ? "robot" : model->name;
  entity.kind = EntityKind::FixedRobot;
  entity.model = model;
  system.add(entity);
  const CollisionModel collision(system, CollisionOptions{}, cache);
  const int default_needed =
      static_cast<int>(std::ceil(options.default_fraction * options.samples - 1e-9));
  const std::vector<PairTally> tallies =
      tally_samples(system.entity(0), collision, system, options, default_needed);

  CollisionMatrix matrix;
  matrix.robot = model->name;
  matrix.samples = options.samples;
  matrix.seed = options.seed;
  const std::vector<CollisionLink>& links = collision.links();
  for (size_t a = 0; a < links.size(); ++a) {
    for (size_t b = a + 1; b < links.size(); ++b) {
      MatrixPair pair{links[a].link, links[b].link, DisabledReason::Adjacent, 0};
      // With one entity, no options and a fixed root, every pair the model leaves out is joined
      // (the only other reason, "static", concerns links that are all on the root's body).
      const int p = collision.find_pair(0, pair.link_a, 0, pair.link_b);
      if (p >= 0) {
        const PairTally& t = tallies[p];
        pair.collisions = t.collisions;
        if (t.collisions == options.samples) {
          pair.reason = DisabledReason::Always;
        } else if (t.at_neutral && t.collisions >= default_needed) {
          pair.reason = DisabledReason::Default;
        } else if (options.include_never && t.collisions == 0) {
          pair.reason = DisabledReason::Never;
        } else {
          continue;
        }
      }
      matrix.pairs.push_back(pair);
    }
  }
  return matrix;
}

std::string describe_counts(const CollisionMatrix& matrix) {
  std::string text = std::to_string(matrix.count(DisabledReason::Adjacent)) + " adjacent, " +
                     std::to_string(matrix.count(DisabledReason::Always)) + " always";
  for (DisabledReason reason : {DisabledReason::Default, DisabledReason::Never}) {
    const int n = matrix.count(reason);
    if (n > 0) text += ", " + std::to_string(n) + " " + to_string(reason);
  }
  return text + " in collision over " + std::to_string(matrix.samples) + " samples, seed " +
         std::to_string(matrix.seed);
}

namespace {

std::string xml_escaped(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      case '"':
        out += "&quot;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

}  // namespace

std::string collision_matrix_srdf(const Model& model, const CollisionMatrix& matrix) {
  std::string out = "<?xml version=\"1.0\"?>\n";
  out +=
      "<!-- Self-collision matrix computed by stanceplan (" + describe_counts(matrix) + "). -->\n";
  out += "<robot name=\"" + xml_escaped(model.name) + "\">\n";
  for (const MatrixPair& p : matrix.pairs) {
    out += "  <disable_collisions link1=\"" + xml_escaped(model.links[p.link_a].name) +
           "\" link2=\"" + xml_escaped(model.links[p.link_b].name) + "\" reason=\"" +
           srdf_reason(p.reason) + "\"/>\n";
  }
  return out + "</robot>\n";
}

}  // namespace stanceplan
