// Signed distance (E20) and its gradient with respect to the full system configuration (E48)
// against central finite differences, for separated and penetrating pairs of every shape kind, on
// a fixed-base arm (revolute joints), a floating-base body (quaternion root) and the environment.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <string>

#include "tests/planner/collision/collision_test_scene.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using test::Scene;

struct GradientError {
  double max_abs = 0.0;  // max over q of |fd - analytic|
  double max_rel = 0.0;  // max over q of |fd - analytic| / max(1, |analytic|)
};

// Central differences of the whole pipeline (forward kinematics, shape poses, FCL).
GradientError compare_with_finite_differences(Scene& s, const Eigen::VectorXd& q, int pair,
                                              double h) {
  const DistanceResult result = s.distance(q, pair);
  Eigen::RowVectorXd dense(s.system.nq());
  signed_distance_gradient(s.system, s.data, *s.model, pair, result, *s.work, dense);

  // The sparse form holds the same numbers.
  const GradientBlocks blocks = gradient_blocks(s.system, *s.model, pair);
  Eigen::RowVectorXd sparse(blocks.total_size());
  signed_distance_gradient_sparse(s.system, s.data, *s.model, pair, result, *s.work, sparse);
  Eigen::RowVectorXd scattered = Eigen::RowVectorXd::Zero(s.system.nq());
  int column = 0;
  for (int b = 0; b < blocks.count; ++b) {
    scattered.segment(blocks.offset[b], blocks.size[b]) = sparse.segment(column, blocks.size[b]);
    column += blocks.size[b];
  }
  EXPECT_LE((scattered - dense).cwiseAbs().maxCoeff(), 1e-14);

  GradientError error;
  for (int i = 0; i < s.system.nq(); ++i) {
    Eigen::VectorXd q_plus = q, q_minus = q;
    q_plus[i] += h;
    q_minus[i] -= h;
    const double fd =
        (s.distance(q_plus, pair).distance - s.distance(q_minus, pair).distance) / (2.0 * h);
    const double abs_error = std::abs(fd - dense[i]);
    error.max_abs = std::max(error.max_abs, abs_error);
    error.max_rel = std::max(error.max_rel, abs_error / std::max(1.0, std::abs(dense[i])));
  }
  s.set(q);
  return error;
}

// Moves the body (its base position) along dir so that `pair` is at distance `target`: s = 0 puts
// the centres of the two links' bounding spheres together.
Eigen::VectorXd place_body(Scene& s, Eigen::VectorXd q, int pair, double target,
                           const Eigen::Vector3d& dir) {
  const CollisionPair& p = s.model->pairs()[pair];
  const CollisionLink& on_body =
      s.model->links()[p.a].entity == s.body ? s.model->links()[p.a] : s.model->links()[p.b];
  const CollisionLink& other =
      &on_body == &s.model->links()[p.a] ? s.model->links()[p.b] : s.model->links()[p.a];
  s.set(q);
  const int base = s.system.offset(s.body);
  const Eigen::Vector3d p_WB = q.segment<3>(base);
  const Eigen::Vector3d offset = s.data[s.body].T_WL[on_body.link] * on_body.center_L - p_WB;
  const Eigen::Vector3d c_W = s.data[other.entity].T_WL[other.link] * other.center_L;
  auto at = [&](double t) {
    Eigen::VectorXd q_t = q;
    q_t.segment<3>(base) = c_W + t * dir.normalized() - offset;
    return q_t;
  };
  const double t =
      test::solve_for([&](double t) { return s.distance(at(t), pair).distance; }, 0.0, 1.0, target);
  return at(t);
}

struct PairCase {
  const char* name;
  const char* link_a;  // on the arm (or floor)
  const char* link_b;  // on the body
  bool a_on_floor;
};

class BodyPairs : public ::testing::TestWithParam<PairCase> {};

TEST_P(BodyPairs, SeparatedAndPenetratingMatchFiniteDifferences) {
  const PairCase& c = GetParam();
  Scene s;
  const int pair = s.pair(c.a_on_floor ? s.floor : s.arm, c.link_a, s.body, c.link_b);
  ASSERT_GE(pair, 0) << c.name;
  const Eigen::Vector3d dir =
      c.a_on_floor ? Eigen::Vector3d(0.1, -0.05, 1.0) : Eigen::Vector3d(0.8, -0.5, 0.45);
  for (double target : {0.03, -0.015}) {
    const Eigen::VectorXd q = place_body(s, s.generic_configuration(), pair, target, dir);
    const DistanceResult r = s.distance(q, pair);
    ASSERT_TRUE(r.ok);
    ASSERT_NEAR(r.distance, target, 1e-9) << c.name;
    // Witness points: distance = n . (p_B - p_A), |n| = 1.
    EXPECT_NEAR(r.normal_W.norm(), 1.0, 1e-12);
    EXPECT_NEAR(r.normal_W.dot(r.p_B_W - r.p_A_W), r.distance, 1e-9) << c.name;
    // Translating B (the body) along the normal increases the distance at rate 1.
    Eigen::VectorXd q_moved = q;
    q_moved.segment<3>(s.system.offset(s.body)) += 1e-5 * r.normal_W;
    EXPECT_NEAR((s.distance(q_moved, pair).distance - r.distance) / 1e-5, 1.0, 1e-3) << c.name;

    const double h = 1e-6;
    const GradientError e = compare_with_finite_differences(s, q, pair, h);
    std::printf("[ %-22s ] d = %+.3f  max |fd - grad| = %.2e (rel %.2e)\n", c.name, target,
                e.max_abs, e.max_rel);
    EXPECT_LE(e.max_rel, 1e-6) << c.name << " at distance " << target;
  }
}

INSTANTIATE_TEST_SUITE_P(ShapeKinds, BodyPairs,
                         ::testing::Values(PairCase{"box-box", "upper", "torso", false},
                                           PairCase{"sphere-box", "hand", "torso", false},
                                           PairCase{"cylinder-box", "fore", "torso", false},
                                           PairCase{"box-convex", "upper", "limb", false},
                                           PairCase{"sphere-convex", "hand", "limb", false},
                                           PairCase{"convex-convex", "finger", "limb", false},
                                           PairCase{"floor-box", "ground", "torso", true}),
                         [](const ::testing::TestParamInfo<PairCase>& info) {
                           std::string name = info.param.name;
                           for (char& ch : name)
                             if (ch == '-') ch = '_';
                           return name;
                         });

TEST(SignedDistance, SameEntityPairHasOneGradientBlock) {
  Scene s;
  const int pair = s.pair(s.arm, "upper", s.arm, "hand");
  ASSERT_GE(pair, 0);
  const GradientBlocks blocks = gradient_blocks(s.system, *s.model, pair);
  ASSERT_EQ(blocks.count, 1);
  EXPECT_EQ(blocks.entity[0], s.arm);
  EXPECT_EQ(blocks.offset[0], s.system.offset(s.arm));
  EXPECT_EQ(blocks.size[0], 4);
  // Swing the forearm down (j2) until the hand's sphere reaches the upper arm's box.
  for (double target : {0.02, -0.01}) {
    const Eigen::VectorXd q0 = s.generic_configuration();
    auto at = [&](double j2) {
      Eigen::VectorXd q = q0;
      q[s.system.offset(s.arm) + 1] = j2;
      return q;
    };
    const double j2 = test::solve_for([&](double a) { return s.distance(at(a), pair).distance; },
                                      1.0, 1.6, target);
    const Eigen::VectorXd q = at(j2);
    ASSERT_NEAR(s.distance(q, pair).distance, target, 1e-9);
    const GradientError e = compare_with_finite_differences(s, q, pair, 1e-6);
    std::printf("[ %-22s ] d = %+.3f  max |fd - grad| = %.2e (rel %.2e)\n", "same entity sph-box",
                target, e.max_abs, e.max_rel);
    EXPECT_LE(e.max_rel, 1e-6);
  }
}

TEST(SignedDistance, FloorPairGradientIsOnlyTheBodyBlock) {
  Scene s;
  const int pair = s.pair(s.floor, "ground", s.body, "torso");
  ASSERT_GE(pair, 0);
  const GradientBlocks blocks = gradient_blocks(s.system, *s.model, pair);
  ASSERT_EQ(blocks.count, 1);  // the environment has no dofs
  EXPECT_EQ(blocks.entity[0], s.body);
  EXPECT_EQ(blocks.size[0], 8);
}

// distance_lower_bound never exceeds the distance (random configurations, every pair), and its
// link-frame boxes make it far tighter than the bounding spheres for a flat link: the 4 m floor's
// sphere (radius 2 m) would keep every link "near" it.
TEST(SignedDistance, LowerBoundIsSoundAndTheBoxesTightenItForAFlatLink) {
  Scene s;
  std::srand(7);
  const auto uniform = [] { return 2.0 * double(std::rand()) / RAND_MAX - 1.0; };
  const int floor_torso = s.pair(s.floor, "ground", s.body, "torso");
  ASSERT_GE(floor_torso, 0);
  double tightest_gain = 0.0;
  for (int trial = 0; trial < 300; ++trial) {
    Eigen::VectorXd q = s.generic_configuration();
    for (int i = 0; i < 4; ++i) q[s.system.offset(s.arm) + i] = 3.0 * uniform();
    q.segment(s.system.offset(s.body), 3) << 0.6 * uniform(), 0.6 * uniform(),
        0.5 * uniform() + 0.4;
    const Eigen::Vector4d quat(uniform(), uniform(), uniform(), uniform());
    q.segment<4>(s.system.offset(s.body) + Entity::kBaseQuaternion) = quat.normalized();
    q[s.system.offset(s.body) + 7] = 3.0 * uniform();
    s.set(q);
    for (int p = 0; p < int(s.model->pairs().size()); ++p) {
      const double bound = distance_lower_bound(*s.model, s.data, p);
      const DistanceResult r = signed_distance(*s.model, *s.work, p);
      ASSERT_LE(bound, r.distance + 1e-12) << "pair " << p << " trial " << trial;
    }
    const CollisionLink& a = s.model->links()[s.model->pairs()[floor_torso].a];
    const CollisionLink& b = s.model->links()[s.model->pairs()[floor_torso].b];
    const double spheres =
        (s.data[b.entity].T_WL[b.link] * b.center_L - s.data[a.entity].T_WL[a.link] * a.center_L)
            .norm() -
        a.radius - b.radius;
    tightest_gain =
        std::max(tightest_gain, distance_lower_bound(*s.model, s.data, floor_torso) - spheres);
  }
  EXPECT_GT(tightest_gain, 1.0);  // m: the sphere bound is below -1.5 m, the box bound near d
}

TEST(SignedDistance, AxisAlignedBoxesGiveExactDepthAndWitnessPoints) {
  // Torso (0.2 x 0.15 x 0.25, identity orientation) against the floor's top face at z = 0.
  Scene s;
  const int pair = s.pair(s.floor, "ground", s.body, "torso");
  Eigen::VectorXd q = s.system.neutral_configuration();
  q.segment(s.system.offset(s.arm), 4) << 0.0, -1.0, 0.0, 0.0;  // arm out of the way
  q.segment<3>(s.system.offset(s.body)) << 1.0, 1.0, 0.125 + 0.2;
  DistanceResult r = s.distance(q, pair);
  EXPECT_NEAR(r.distance, 0.2, 1e-9);
  EXPECT_NEAR((r.normal_W - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-9);
  EXPECT_NEAR(r.p_A_W.z(), 0.0, 1e-9);
  EXPECT_NEAR(r.p_B_W.z(), 0.2, 1e-9);
  q[s.system.offset(s.body) + 2] = 0.125 - 0.03;
  r = s.distance(q, pair);
  EXPECT_NEAR(r.distance, -0.03, 1e-9);
  EXPECT_NEAR((r.normal_W - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-9);
  EXPECT_NEAR(r.p_A_W.z(), 0.0, 1e-9);    // floor's point deepest inside the torso
  EXPECT_NEAR(r.p_B_W.z(), -0.03, 1e-9);  // torso's point deepest inside the floor
}

TEST(SignedDistance, ExactlyTouchingBoxesGiveZero) {
  // A box resting exactly on the floor: the stance planner's everyday configuration.
  Scene s;
  const int pair = s.pair(s.floor, "ground", s.body, "torso");
  Eigen::VectorXd q = s.system.neutral_configuration();
  q.segment(s.system.offset(s.arm), 4) << 0.0, -1.0, 0.0, 0.0;
  for (double yaw : {0.0, 0.3}) {
    q.segment<3>(s.system.offset(s.body)) << 1.0, 1.0, 0.125;
    q.segment<4>(s.system.offset(s.body) + 3) << std::cos(yaw / 2), 0, 0, std::sin(yaw / 2);
    const DistanceResult r = s.distance(q, pair);
    EXPECT_TRUE(r.ok);
    EXPECT_NEAR(r.distance, 0.0, 1e-12) << "yaw " << yaw;
    // The normal comes from witness points 1e-6 apart: accurate to about 1e-9.
    EXPECT_NEAR((r.normal_W - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-7) << "yaw " << yaw;
    EXPECT_NEAR(r.p_A_W.z(), 0.0, 1e-12);
    EXPECT_NEAR(r.p_B_W.z(), 0.0, 1e-12);
  }
}

// A configuration with NaN (a diverging solve's iterate) has no distance: NaN and not ok, and no
// call into FCL, whose libccd GJK asserts and aborts the process on such poses (it once ended a
// search of the dual-arm hand-over with pads allowed on any facet).
TEST(SignedDistance, ANonFiniteConfigurationGivesNaNNotACrash) {
  Scene s;
  const int pair = s.pair(s.floor, "ground", s.body, "torso");
  Eigen::VectorXd q = s.system.neutral_configuration();
  q.segment(s.system.offset(s.arm), 4) << 0.0, -1.0, 0.0, 0.0;
  q.segment<3>(s.system.offset(s.body)) << 1.0, 1.0, 0.5;
  ASSERT_TRUE(s.distance(q, pair).ok);
  q(s.system.offset(s.body)) = std::numeric_limits<double>::quiet_NaN();
  const DistanceResult r = s.distance(q, pair);
  EXPECT_FALSE(r.ok);
  EXPECT_TRUE(std::isnan(r.distance));
}

TEST(SignedDistance, SphereBoxSeparationAndPenetrationDepth) {
  // The hand's sphere (r = 0.05) against the floor (separated), then against the torso's bottom
  // face placed 0.03 above the sphere's centre (penetration depth 0.02).
  Scene s;
  Eigen::VectorXd q = s.system.neutral_configuration();
  q.segment(s.system.offset(s.arm), 4) << 0.0, 1.5707963267948966, 0.0, 0.0;  // forearm down
  s.set(q);
  const Eigen::Vector3d c_W = s.data[s.arm].T_WL[s.system.entity(s.arm).model->find_link("hand")] *
                              Eigen::Vector3d(0.02, 0, 0);
  const int floor_pair = s.pair(s.floor, "ground", s.arm, "hand");
  ASSERT_GE(floor_pair, 0);
  EXPECT_NEAR(s.distance(q, floor_pair).distance, c_W.z() - 0.05, 1e-9);

  const int torso_pair = s.pair(s.arm, "hand", s.body, "torso");
  ASSERT_GE(torso_pair, 0);
  q.segment<3>(s.system.offset(s.body)) = c_W + Eigen::Vector3d(0, 0, 0.125 + 0.03);
  const DistanceResult r = s.distance(q, torso_pair);
  EXPECT_NEAR(r.distance, -0.02, 1e-6);
  EXPECT_NEAR((r.normal_W - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-6);
}

TEST(SignedDistance, TalosHullPairsMatchFiniteDifferences) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  // Real meshes (simplified hulls grown by their margins, mirrored ones included) on a floating
  // base, at a random posture: a few separated and every penetrating candidate pair.
  UrdfOptions urdf;
  urdf.packages.directories = {test::talos_package_dir()};
  urdf.packages.use_ros_package_path = false;
  System system;
  system.add(Entity{"talos", EntityKind::FloatingRobot,
                    std::make_shared<Model>(load_urdf(test::talos_urdf(), urdf))});
  CollisionOptions options;
  options.srdf_files.push_back(
      {"talos", test::shared_path("robots/talos/robots/talos_data/srdf/talos.srdf")});
  const CollisionModel model(system, options);
  CollisionData work(system, model);
  std::vector<ModelData> data;
  data.emplace_back(system.entity(0));
  auto distance = [&](const Eigen::VectorXd& q, int pair) {
    forward_kinematics(system.entity(0), q, data[0]);
    work.update(model, data);
    return signed_distance(model, work, pair);
  };
  Eigen::VectorXd q = system.neutral_configuration();
  q.head<3>() << 0.1, -0.2, 1.0;
  q.segment<4>(3) = Eigen::Vector4d(0.95, 0.1, -0.2, 0.15).normalized();
  std::srand(7);
  q.tail(system.nq() - 7) = 0.4 * Eigen::VectorXd::Random(system.nq() - 7);
  int separated = 0, penetrating = 0;
  double worst = 0.0;
  for (int pair = 0; pair < static_cast<int>(model.pairs().size()); ++pair) {
    const DistanceResult r = distance(q, pair);
    ASSERT_TRUE(r.ok);
    if (r.distance >= 0.0 && (r.distance > 0.05 || separated >= 6)) continue;
    (r.distance < 0.0 ? penetrating : separated)++;
    Eigen::RowVectorXd gradient(system.nq());
    signed_distance_gradient(system, data, model, pair, r, work, gradient);
    const double h = 1e-6;
    for (int i = 0; i < system.nq(); ++i) {
      Eigen::VectorXd q_plus = q, q_minus = q;
      q_plus[i] += h;
      q_minus[i] -= h;
      const double fd =
          (distance(q_plus, pair).distance - distance(q_minus, pair).distance) / (2 * h);
      const double error = std::abs(fd - gradient[i]) / std::max(1.0, std::abs(gradient[i]));
      worst = std::max(worst, error);
      EXPECT_LE(error, 1e-6) << "pair " << pair << " d = " << r.distance << " q[" << i << "]";
    }
    distance(q, pair);
  }
  std::printf("[ TALOS hulls ] %d separated, %d penetrating pairs: max rel |fd - grad| = %.2e\n",
              separated, penetrating, worst);
  EXPECT_GE(separated, 3);
}

}  // namespace
}  // namespace stanceplan
