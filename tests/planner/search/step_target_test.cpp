// Case-1 step targets (planner/search/step_target.h): a step that would cross another contact on
// the same surface (the trailing foot of a side-step aimed past the leading one) stops short of it;
// every other step aims where it did before.
#include <gtest/gtest.h>

#include "planner/search/step_target.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

class StepTarget : public ::testing::Test {
 protected:
  const Scene scene = test::humanoid_scene("wall");
  const Contact left = test::task(scene, "robot/l_sole", "env/floor").contact;
  const Contact right = test::task(scene, "robot/r_sole", "env/floor").contact;
  const Stance on_left = Stance({left});
  const std::vector<Placement> left_at_origin = {Placement{0.0, 0.0, 0.0}};
};

TEST_F(StepTarget, FootprintIsTheSoleOnTheFloor) {
  // The sole is 0.22 x 0.13 m, its frame at the vertex centroid, x forward.
  const auto sole = footprint_S2(scene.surfaces.get(left.s1), Placement{1.0, 2.0, M_PI / 2});
  ASSERT_EQ(sole.size(), 4u);
  double x_min = 9, x_max = -9, y_min = 9, y_max = -9;
  for (const Eigen::Vector2d& v : sole) {
    x_min = std::min(x_min, v.x()), x_max = std::max(x_max, v.x());
    y_min = std::min(y_min, v.y()), y_max = std::max(y_max, v.y());
  }
  // Turned by 90 degrees: 0.13 m along x, 0.22 m along y.
  EXPECT_NEAR(x_max - x_min, 0.13, 1e-12);
  EXPECT_NEAR(y_max - y_min, 0.22, 1e-12);
  EXPECT_TRUE(footprint_contains(sole, {1.0, 2.0}));
  EXPECT_FALSE(footprint_contains(sole, {1.07, 2.0}));
  const auto other =
      footprint_S2(scene.surfaces.get(left.s1), Placement{1.0 + 0.13 + 0.05, 2.0, M_PI / 2});
  EXPECT_NEAR(footprint_separation(sole, other), 0.05, 1e-12);
  EXPECT_LT(footprint_separation(sole, sole), 0.0);
}

// A point surface (a round tip of radius r) has no polygon: its footprint is the square of
// half-side r around its contact point, whatever theta.
TEST_F(StepTarget, APointsFootprintIsASquareOfItsRadius) {
  Surface tip;
  std::string error;
  ASSERT_TRUE(
      make_point_surface("tip", 0, "base", Eigen::Vector3d(0.1, 0.0, 0.0), 0.02, &tip, &error));
  const auto square = footprint_S2(tip, Placement{1.0, 2.0, 0.7});
  ASSERT_EQ(square.size(), 4u);
  EXPECT_TRUE(footprint_contains(square, {1.019, 2.019}));
  EXPECT_FALSE(footprint_contains(square, {1.021, 2.0}));
  const auto other = footprint_S2(tip, Placement{1.1, 2.0, 0.0});
  EXPECT_NEAR(footprint_separation(square, other), 0.1 - 0.04, 1e-12);
}

TEST_F(StepTarget, SideStepPastTheOtherFootStopsBesideIt) {
  // Right foot lifted at y = -0.17, aimed at y = +0.115: past the left foot (y in [-0.065, 0.065]).
  const Placement now{0.0, -0.17, 0.0}, aim{0.02, 0.115, 0.0};
  const Placement t = step_target(scene, on_left, left_at_origin, right, now, aim, 1.0);
  // The farthest twentieth of the way that keeps 2 cm from the left foot: the first.
  EXPECT_DOUBLE_EQ(t.y, -0.17 + 0.285 / 20);
  EXPECT_DOUBLE_EQ(t.x, 0.02 / 20);
  EXPECT_DOUBLE_EQ(t.theta, 0.0);
  const auto mine = footprint_S2(scene.surfaces.get(right.s1), t);
  EXPECT_GE(
      footprint_separation(mine, footprint_S2(scene.surfaces.get(left.s1), left_at_origin[0])),
      kStepTargetClearance);
}

TEST_F(StepTarget, StepsThatCrossNothingAreUnchanged) {
  // A forward step beside the left foot, its toes 1 mm over the left foot's edge: left to the
  // solver.
  const Placement now{-0.15, -0.17, 0.0}, aim{0.15, -0.129, 0.0};
  const Placement full = step_target(scene, on_left, left_at_origin, right, now, aim, 1.0);
  EXPECT_EQ(full.x, aim.x);
  EXPECT_EQ(full.y, aim.y);
  const Placement half = step_target(scene, on_left, left_at_origin, right, now, aim, 0.5);
  EXPECT_EQ(half.x, now.x + 0.5 * (aim.x - now.x));
  EXPECT_EQ(half.y, now.y + 0.5 * (aim.y - now.y));
  // No other contact on the floor: the aim itself.
  const Placement alone = step_target(scene, Stance(std::vector<Contact>{}), {}, right, now,
                                      Placement{0.0, 0.0, 0.0}, 1.0);
  EXPECT_EQ(alone.y, 0.0);
}

// Where a solve aimed past the floor's edge can put the sole (landing_estimate, used to predict
// loops): the last point of the way where the footprint is still inside the floor's polygon.
TEST_F(StepTarget, ASoleAimedPastTheEdgeLandsAtTheEdge) {
  const Surface& floor = scene.surfaces.get(right.s2);
  double x_edge = -1e9;
  for (const Eigen::Vector2d& v : floor.vertices_S) x_edge = std::max(x_edge, v.x());
  // The sole (0.22 m long, its frame at the centre) from 0.5 m inside the edge to 0.3 m past it.
  const Placement now{x_edge - 0.5, -0.1, 0.0}, aim{x_edge + 0.3, -0.1, 0.0};
  const Placement landed = landing_estimate(scene, right, now, aim);
  EXPECT_NEAR(landed.x, x_edge - 0.11, 1e-5);
  EXPECT_NEAR(landed.y, -0.1, 1e-12);
  EXPECT_EQ(landed.theta, 0.0);
  // Inside, the aim itself; from outside (nothing fits on the way's start), the aim too.
  const Placement inside{x_edge - 0.2, 0.0, 0.3};
  EXPECT_EQ(landing_estimate(scene, right, now, inside).x, inside.x);
  const Placement outside{x_edge + 0.2, 0.0, 0.0};
  EXPECT_EQ(landing_estimate(scene, right, outside, aim).x, aim.x);
}

}  // namespace
}  // namespace stanceplan
