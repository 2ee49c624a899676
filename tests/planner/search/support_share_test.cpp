// The support-share ordering (support_share.h): at the guide's posture a sole above a tread ranks
// before the other treads and before a knee, removals come first, ties keep their order.
#include <gtest/gtest.h>

#include "planner/model/kinematics.h"
#include "planner/search/support_share.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

Candidate add(const Scene& scene, const std::string& s1, const std::string& s2) {
  return {true, test::task(scene, s1, s2).contact};
}

std::string name(const Scene& scene, const Candidate& c) {
  return std::string(c.add ? "+" : "-") + scene.surfaces.id(scene.system, c.contact.s1) + "@" +
         scene.surfaces.id(scene.system, c.contact.s2);
}

TEST(SupportShare, ScoresTheGapAndTheNormalsAtTheGuidePosture) {
  const Scene scene = test::humanoid_scene("flat_ground");
  const auto standing = system_kinematics(scene.system, test::standing_configuration(scene));
  // A sole on the floor it stands on: realised (gap 0, normals opposed).
  EXPECT_NEAR(support_share_score(scene, standing, add(scene, "robot/l_sole", "env/floor").contact),
              0.0, 1e-6);
  // A knee while standing: its normal (+x of the shank) at right angles to the floor's, the knee
  // about half a metre above it: 0.2 m for the normals plus the gap.
  const double knee =
      support_share_score(scene, standing, add(scene, "robot/l_knee", "env/floor").contact);
  const Surface& s = scene.surfaces.get(test::surface(scene, "robot/l_knee"));
  double lowest = INFINITY;
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const Eigen::Vector3d& v : s.vertices_L()) {
    lowest = std::min(lowest, (standing[0].T_WL[s.link] * v).z());
    centre += standing[0].T_WL[s.link] * v / double(s.vertices_L().size());
  }
  // The floor reaches far beyond the knee: both gaps are heights above it.
  EXPECT_NEAR(
      knee,
      (1 - kShareCentreWeight) * lowest + kShareCentreWeight * centre.z() + kShareNormalWeight,
      1e-6);
  EXPECT_GT(knee, 0.4);
}

// A sole whose middle is 5 cm past a tread's far edge, its heel still on the tread: it touches
// (surface_gap 0) but is 5 cm from lying on it (the centre gap), and scores a quarter of that.
TEST(SupportShare, ASoleHangingOverAnEdgeScoresPartOfItsCentresDistance) {
  const Scene scene = test::humanoid_scene("stairs");
  Eigen::VectorXd q = test::standing_configuration(scene);
  q[2] = 0.93 + 0.5;  // the soles at tread 5's height (x 1.55-2.15 m)
  const SurfaceRef sole = test::surface(scene, "robot/l_sole");
  const Surface& s = scene.surfaces.get(sole);
  auto sole_centre_x = [&](const std::vector<ModelData>& data) {
    double x = 0.0;
    for (const Eigen::Vector3d& v : s.vertices_L())
      x += (data[0].T_WL[s.link] * v).x() / double(s.vertices_L().size());
    return x;
  };
  q[0] += 2.20 - sole_centre_x(system_kinematics(scene.system, q));
  const auto data = system_kinematics(scene.system, q);
  ASSERT_NEAR(sole_centre_x(data), 2.20, 1e-9);
  const SurfaceRef tread = test::surface(scene, "env/tread_5");
  EXPECT_NEAR(surface_gap(scene, data, sole, tread), 0.0, 1e-6);
  const SurfaceGaps gaps = surface_gaps(scene, data, sole, tread);
  EXPECT_NEAR(gaps.touching, 0.0, 1e-6);
  EXPECT_NEAR(gaps.centre, 0.05, 1e-6);
  EXPECT_NEAR(support_share_score(scene, data, add(scene, "robot/l_sole", "env/tread_5").contact),
              kShareCentreWeight * 0.05, 1e-6);
}

// The guide's posture: standing with the waist above tread 5 (x 1.55-2.15 m, z = 0.5 m).
auto guide_above_tread_5(const Scene& scene) {
  Eigen::VectorXd q = test::standing_configuration(scene);
  q[0] = 1.7;
  q[2] = 0.93 + 0.5;
  return system_kinematics(scene.system, q);
}

TEST(SupportShare, OrdersTheSoleAboveTheGuidedTreadFirst) {
  const Scene scene = test::humanoid_scene("stairs");
  const auto guide = guide_above_tread_5(scene);
  std::vector<Candidate> list = {add(scene, "robot/r_sole", "env/floor"),
                                 add(scene, "robot/r_knee", "env/tread_5"),
                                 add(scene, "robot/r_sole", "env/tread_3"),
                                 {false, test::task(scene, "robot/l_sole", "env/tread_5").contact},
                                 add(scene, "robot/r_sole", "env/tread_5"),
                                 add(scene, "robot/r_sole", "env/tread_4")};
  const std::vector<double> scores = order_by_support_share(scene, guide, list, -1.0);
  ASSERT_EQ(list.size(), 6u);
  EXPECT_EQ(name(scene, list[0]), "-robot/l_sole@env/tread_5");  // removals first
  EXPECT_EQ(scores[0], 0.0);
  EXPECT_EQ(name(scene, list[1]), "+robot/r_sole@env/tread_5");
  EXPECT_NEAR(scores[1], 0.0, 1e-6);
  EXPECT_EQ(name(scene, list[2]), "+robot/r_sole@env/tread_4");
  EXPECT_EQ(name(scene, list[3]), "+robot/r_sole@env/tread_3");
  EXPECT_TRUE(std::is_sorted(scores.begin() + 1, scores.end()));
  // Ties keep the given order: two removals stay as given.
  std::vector<Candidate> removals = {
      {false, test::task(scene, "robot/r_sole", "env/floor").contact},
      {false, test::task(scene, "robot/l_sole", "env/floor").contact}};
  order_by_support_share(scene, guide, removals, -1.0);
  EXPECT_EQ(name(scene, removals[0]), "-robot/r_sole@env/floor");
}

// An addition the guide's posture already realises (within `realised`) comes before the removals:
// the sole standing on the guided tread is placed before any contact is lifted, the tread 10 cm
// below it still after them.
TEST(SupportShare, PutsAdditionsTheGuideRealisesBeforeRemovals) {
  const Scene scene = test::humanoid_scene("stairs");
  const auto guide = guide_above_tread_5(scene);
  std::vector<Candidate> list = {add(scene, "robot/r_sole", "env/tread_4"),
                                 {false, test::task(scene, "robot/l_sole", "env/floor").contact},
                                 add(scene, "robot/r_sole", "env/tread_5")};
  const std::vector<double> scores = order_by_support_share(scene, guide, list, 0.03);
  ASSERT_EQ(list.size(), 3u);
  EXPECT_EQ(name(scene, list[0]), "+robot/r_sole@env/tread_5");
  EXPECT_LE(scores[0], 0.03);
  EXPECT_EQ(name(scene, list[1]), "-robot/l_sole@env/floor");
  EXPECT_EQ(name(scene, list[2]), "+robot/r_sole@env/tread_4");
  EXPECT_GT(scores[2], 0.03);
}

}  // namespace
}  // namespace stanceplan
