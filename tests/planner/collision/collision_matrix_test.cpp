// The computed self-collision matrix (planner/collision/collision_matrix.h): the exact pairs of
// models written for it, determinism, the opt-in "never", the SRDF round trip, how the scene
// builder applies it, and TALOS against its own SRDF.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <utility>

#include "planner/collision/collision_matrix.h"
#include "planner/collision/collision_model.h"
#include "planner/collision/signed_distance.h"
#include "planner/collision/srdf.h"
#include "planner/model/kinematics.h"
#include "planner/model/urdf_loader.h"
#include "planner/scene/scene_builder.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using Named = std::tuple<std::string, std::string, std::string, int>;  // link1, link2, reason, hits

std::shared_ptr<const Model> load(const std::string& path, const std::string& package_dir = "") {
  UrdfOptions options;
  if (!package_dir.empty()) options.packages.directories = {package_dir};
  return std::make_shared<const Model>(load_urdf(path, options));
}

std::shared_ptr<const Model> two_finger_arm() {
  return load(test::source_path("tests/data/collision_matrix/two_finger_arm.urdf"));
}

std::vector<Named> named(const Model& model, const CollisionMatrix& matrix) {
  std::vector<Named> out;
  for (const MatrixPair& p : matrix.pairs)
    out.emplace_back(model.links[p.link_a].name, model.links[p.link_b].name, to_string(p.reason),
                     p.collisions);
  return out;
}

std::vector<Named> without_reason(std::vector<Named> pairs, const std::string& reason) {
  std::erase_if(pairs, [&](const Named& p) { return std::get<2>(p) == reason; });
  return pairs;
}

TEST(CollisionMatrix, TwoFingerArmDisablesItsJointsAndExactlyTheThreeOverlappingPairs) {
  const auto model = two_finger_arm();
  const CollisionMatrix matrix = compute_collision_matrix(model);
  EXPECT_EQ(matrix.robot, "two_finger_arm");
  EXPECT_EQ(matrix.samples, 1000);
  EXPECT_EQ(matrix.seed, 0u);
  // Finger bases hang from the palm through a link without geometry (two movable joints): sampled,
  // not adjacent. Tips are sometimes in collision with the palm and each other: kept.
  const std::vector<Named> expected = {{"base", "turret", "adjacent", 0},
                                       {"turret", "upper_arm", "adjacent", 0},
                                       {"upper_arm", "forearm", "adjacent", 0},
                                       {"forearm", "palm", "adjacent", 0},
                                       {"palm", "finger_1_base", "always", 1000},
                                       {"palm", "finger_2_base", "always", 1000},
                                       {"finger_1_base", "finger_1_tip", "adjacent", 0},
                                       {"finger_1_base", "finger_2_base", "always", 1000},
                                       {"finger_2_base", "finger_2_tip", "adjacent", 0}};
  EXPECT_EQ(named(*model, matrix), expected);
  EXPECT_EQ(matrix.num_sampled(), 3);
  EXPECT_EQ(describe_counts(matrix), "6 adjacent, 3 always in collision over 1000 samples, seed 0");
}

TEST(CollisionMatrix, SameSeedSameMatrixAndAnotherSeedChangesOnlySampledShares) {
  const auto model = two_finger_arm();
  CollisionMatrixOptions options;
  options.include_never = true;  // the reason most sensitive to the samples drawn
  const CollisionMatrix first = compute_collision_matrix(model, options);
  const CollisionMatrix again = compute_collision_matrix(model, options);
  EXPECT_EQ(named(*model, first), named(*model, again));
  options.seed = 7;
  const CollisionMatrix other = compute_collision_matrix(model, options);
  EXPECT_EQ(other.seed, 7u);
  // Structural overlaps and adjacency do not depend on the seed; "never" (and, near their
  // thresholds, "always" and "default") may.
  EXPECT_EQ(without_reason(named(*model, first), "never"),
            without_reason(named(*model, other), "never"));
}

TEST(CollisionMatrix, NeverIsOptInAndOnlyTakesPairsNoSampleBroughtTogether) {
  const auto model = two_finger_arm();
  const CollisionMatrix usual = compute_collision_matrix(model);
  EXPECT_EQ(usual.count(DisabledReason::Never), 0);
  CollisionMatrixOptions options;
  options.include_never = true;
  const CollisionMatrix with_never = compute_collision_matrix(model, options);
  EXPECT_GT(with_never.count(DisabledReason::Never), 0);
  for (const MatrixPair& p : with_never.pairs)
    if (p.reason == DisabledReason::Never) {
      EXPECT_EQ(p.collisions, 0);
    }
  EXPECT_EQ(without_reason(named(*model, with_never), "never"), named(*model, usual));
  // The tips reach each other and the palm in some samples: never "never".
  const std::vector<Named> pairs = named(*model, with_never);
  for (const Named& p : pairs) {
    EXPECT_FALSE(std::get<0>(p) == "finger_1_tip" && std::get<1>(p) == "finger_2_tip");
    EXPECT_FALSE(std::get<0>(p) == "palm" && std::get<1>(p) == "finger_1_tip");
  }
  std::printf("two_finger_arm with --never: %s\n", describe_counts(with_never).c_str());
}

TEST(CollisionMatrix, DefaultNeedsTheNeutralPostureAndTheShareOfSamples) {
  // slider.urdf: the ball touches the bar for slides below 0.97 m of [0, 1], and at slide 0.
  const auto model = load(test::source_path("tests/data/collision_matrix/slider.urdf"));
  const CollisionMatrix matrix = compute_collision_matrix(model);
  ASSERT_EQ(matrix.pairs.size(), 1u);
  EXPECT_EQ(named(*model, matrix)[0], Named("bar", "ball", "default", 961));
  CollisionMatrixOptions strict;
  strict.default_fraction = 0.99;  // 961 of 1000 is not enough
  EXPECT_TRUE(compute_collision_matrix(model, strict).pairs.empty());
  EXPECT_THROW(compute_collision_matrix(model, {.samples = 0}), std::invalid_argument);
}

TEST(CollisionMatrix, SrdfRoundTripDisablesTheSamePairs) {
  const auto model = two_finger_arm();
  const CollisionMatrix matrix = compute_collision_matrix(model);
  const std::string path = (test::temp_dir("collision_matrix") / "two_finger_arm.srdf").string();
  std::ofstream(path) << collision_matrix_srdf(*model, matrix);
  const std::vector<DisabledCollision> read = load_srdf_disabled_collisions(path);
  ASSERT_EQ(read.size(), matrix.pairs.size());
  for (size_t i = 0; i < read.size(); ++i) {
    EXPECT_EQ(read[i].link1, model->links[matrix.pairs[i].link_a].name);
    EXPECT_EQ(read[i].link2, model->links[matrix.pairs[i].link_b].name);
    EXPECT_EQ(read[i].reason, srdf_reason(matrix.pairs[i].reason));
  }
  // Given back as the robot's SRDF, it leaves out the three sampled pairs, and no matrix is
  // computed for a robot whose SRDF disables pairs.
  System system;
  system.add(Entity{.name = "robot", .kind = EntityKind::FixedRobot, .model = model});
  const CollisionModel plain(system);
  CollisionOptions options_with_srdf;
  options_with_srdf.srdf_files = {{"robot", path}};
  options_with_srdf.computed_matrix = CollisionMatrixOptions{};
  const CollisionModel with_srdf(system, options_with_srdf);
  EXPECT_EQ(with_srdf.num_srdf_disabled_pairs(), 3);
  EXPECT_TRUE(with_srdf.computed_matrices().empty());
  EXPECT_EQ(with_srdf.pairs().size() + 3, plain.pairs().size());
}

TEST(CollisionMatrix, SceneBuilderComputesItForARobotWithoutSrdf) {
  SceneSpec spec;
  EntitySpec robot;
  robot.name = "robot";
  robot.kind = EntityKind::FixedRobot;
  robot.urdf = test::source_path("tests/data/collision_matrix/two_finger_arm.urdf");
  spec.entities.push_back(robot);
  const Scene scene = build_scene(spec);
  ASSERT_EQ(scene.collision->computed_matrices().size(), 1u);
  EXPECT_EQ(scene.collision->computed_matrices()[0].entity, 0);
  EXPECT_EQ(scene.collision->num_computed_disabled_pairs(), 3);
  std::vector<std::string> reasons;
  for (const ExcludedPair& p : scene.collision->excluded_pairs()) reasons.push_back(p.reason);
  EXPECT_EQ(std::count(reasons.begin(), reasons.end(), "computed (always)"), 3);
  EXPECT_EQ(scene.collision->find_pair(0, scene.system.entity(0).model->find_link("palm"), 0,
                                       scene.system.entity(0).model->find_link("finger_1_base")),
            -1);
  spec.collision_matrix.reset();
  const Scene unchanged = build_scene(spec);
  EXPECT_TRUE(unchanged.collision->computed_matrices().empty());
  EXPECT_EQ(unchanged.collision->pairs().size(), scene.collision->pairs().size() + 3);
}

// pair_in_collision is the sign of signed_distance: on random postures of the models, every
// candidate pair agrees except within 1e-9 m of contact.
void expect_sign_of_signed_distance(const std::shared_ptr<const Model>& model, int samples) {
  System system;
  system.add(Entity{.name = "robot", .kind = EntityKind::FixedRobot, .model = model});
  const CollisionModel collision(system);
  std::vector<ModelData> data(1, ModelData(system.entity(0)));
  CollisionData work(system, collision);
  std::mt19937_64 random(11);
  int in_collision = 0;
  for (int s = 0; s < samples; ++s) {
    Eigen::VectorXd q(system.nq());
    for (int k = 0; k < q.size(); ++k) {
      const Joint& joint = model->joints[model->dof_joints[k]];
      q[k] = joint.lower + (joint.upper - joint.lower) * (random() % 1001) / 1000.0;
    }
    forward_kinematics(system.entity(0), q, data[0]);
    work.update(collision, data);
    for (int p = 0; p < static_cast<int>(collision.pairs().size()); ++p) {
      const double d = signed_distance(collision, work, p).distance;
      const bool fast = pair_in_collision(collision, work, data, p);
      in_collision += fast;
      if (std::abs(d) > 1e-9) {
        EXPECT_EQ(fast, d < 0.0) << "pair " << p << " distance " << d;
      }
    }
  }
  EXPECT_GT(in_collision, 0);
}

TEST(CollisionMatrix, PairInCollisionIsTheSignOfTheSignedDistance) {
  expect_sign_of_signed_distance(two_finger_arm(), 200);
  expect_sign_of_signed_distance(load(test::source_path("tests/data/collision_matrix/slider.urdf")),
                                 200);
}

TEST(CollisionMatrix, PairInCollisionIsTheSignOfTheSignedDistanceOnTalos) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  expect_sign_of_signed_distance(load(test::talos_urdf(), test::talos_package_dir()), 20);
}

TEST(CollisionMatrix, ProjectHumanoidHasOnlyAdjacentPairs) {
  const auto model = load(test::source_path("assets/robots/humanoid/humanoid.urdf"));
  const auto start = std::chrono::steady_clock::now();
  const CollisionMatrix matrix = compute_collision_matrix(model);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  EXPECT_EQ(matrix.num_sampled(), 0) << describe_counts(matrix);
  std::printf("humanoid: %s, %.1f ms\n", describe_counts(matrix).c_str(), ms);
}

TEST(CollisionMatrix, TalosContainsTheAdjacentPairsOfItsOwnSrdf) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const auto model = load(test::talos_urdf(), test::talos_package_dir());
  HullCache hulls;
  System system;
  system.add(Entity{.name = "talos", .kind = EntityKind::FixedRobot, .model = model});
  const CollisionModel warm(system, {}, &hulls);  // load the meshes outside the timing
  const auto start = std::chrono::steady_clock::now();
  const CollisionMatrix matrix = compute_collision_matrix(model, {}, &hulls);
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::set<std::pair<std::string, std::string>> computed;
  for (const MatrixPair& p : matrix.pairs) {
    computed.insert({model->links[p.link_a].name, model->links[p.link_b].name});
    computed.insert({model->links[p.link_b].name, model->links[p.link_a].name});
  }
  const std::vector<DisabledCollision> srdf = load_srdf_disabled_collisions(
      test::shared_path("robots/talos/robots/talos_data/srdf/talos.srdf"));
  std::map<std::string, std::pair<int, int>> coverage;  // SRDF reason -> (covered, on this model)
  for (const DisabledCollision& d : srdf) {
    const int l1 = model->find_link(d.link1), l2 = model->find_link(d.link2);
    if (l1 < 0 || l2 < 0 || model->links[l1].collisions.empty() ||
        model->links[l2].collisions.empty())
      continue;  // the SRDF describes the full TALOS; the reduced model lacks some links
    const bool covered = computed.count({d.link1, d.link2}) > 0;
    ++coverage[d.reason].second;
    coverage[d.reason].first += covered;
    if (d.reason == "Adjacent") {
      EXPECT_TRUE(covered) << d.link1 << " / " << d.link2;
    }
  }
  EXPECT_GT(coverage["Adjacent"].second, 0);
  std::printf("talos: %s in %.1f ms; the SRDF's pairs on links with geometry covered:",
              describe_counts(matrix).c_str(), ms);
  for (const auto& [reason, counts] : coverage)
    std::printf(" %s %d of %d;", reason.c_str(), counts.first, counts.second);
  std::printf("\n");
}

}  // namespace
}  // namespace stanceplan
