// The held-object balance test before a removal (planner/search/object_balance.h): nonnegative
// least squares against its optimality conditions, and the paper's dual-arm cylinder at the
// postures of its plan: one pad on a standing cylinder's side cannot hold it, two opposite pads
// can, the platform alone can.
#include <gtest/gtest.h>

#include <optional>
#include <random>

#include "planner/io/scenario.h"
#include "planner/model/kinematics.h"
#include "planner/search/object_balance.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

TEST(NonnegativeLeastSquares, MeetsTheKuhnTuckerConditions) {
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  for (int trial = 0; trial < 50; ++trial) {
    const int m = 6, n = 4 + trial % 20;
    Eigen::MatrixXd A(m, n);
    Eigen::VectorXd b(m);
    for (int i = 0; i < m; ++i) {
      b[i] = normal(rng);
      for (int j = 0; j < n; ++j) A(i, j) = normal(rng);
    }
    Eigen::VectorXd x;
    const double residual = nonnegative_least_squares(A, b, &x);
    EXPECT_NEAR(residual, (A * x - b).norm(), 1e-12);
    const Eigen::VectorXd w = A.transpose() * (b - A * x);  // the negative gradient
    for (int j = 0; j < n; ++j) {
      EXPECT_GE(x[j], 0.0);
      EXPECT_LE(w[j], 1e-9) << trial;  // no descent direction into x_j > 0
      if (x[j] > 0.0) {
        EXPECT_NEAR(w[j], 0.0, 1e-9) << trial;
      }
    }
  }
}

TEST(NonnegativeLeastSquares, ExactWhenBIsAPositiveCombination) {
  Eigen::MatrixXd A(2, 3);
  A << 1, 0, 1, 0, 1, 1;
  Eigen::VectorXd x;
  EXPECT_NEAR(nonnegative_least_squares(A, Eigen::Vector2d(2, 3), &x), 0.0, 1e-12);
  // (1, -1): no nonnegative combination has a negative second row; the best is x = (1, 0, 0).
  EXPECT_NEAR(nonnegative_least_squares(A, Eigen::Vector2d(1, -1), &x), 1.0, 1e-12);
  EXPECT_NEAR(x[0], 1.0, 1e-12);
}

TEST(ObjectBalance, OnePadOnTheCylindersSideCannotHoldItTwoOppositeOnesCan) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/dual_arm_cylinder.yaml"));
  const SearchResult result = test::plan_with_one_process(scenario);
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  const Scene& scene = scenario.scene;
  const double mu = scenario.solver.friction;
  const int K = scenario.solver.cone_generators;
  auto find = [&](const Stance& stance, const std::string& s1) -> std::optional<Contact> {
    for (const Contact& c : stance.contacts())
      if (scene.surfaces.id(scene.system, c.s1) == s1) return c;
    return std::nullopt;
  };
  int one_pad = 0, two_pads = 0;
  for (const PlanStep& step : result.plan.steps) {
    const auto data = system_kinematics(scene.system, step.q);
    const Stance& stance = step.stance;
    const std::optional<Contact> bottom = find(stance, "cyl/bottom");
    if (stance.size() == 2 && bottom) {
      // The bottom on the platform and one pad: without the bottom the pad's cone (normal
      // horizontal) cannot carry the weight; without the pad the platform carries it.
      ++one_pad;
      EXPECT_FALSE(objects_balance_without(scene, data, stance, *bottom, mu, K));
      const Contact pad =
          stance.contacts()[0] == *bottom ? stance.contacts()[1] : stance.contacts()[0];
      EXPECT_TRUE(objects_balance_without(scene, data, stance, pad, mu, K));
    }
    if (stance.size() == 3 && bottom && step.action == "add" &&
        scene.surfaces.id(scene.system, step.changed->s1) == "arm1/pad_l") {
      // Both arm 1 pads on opposite sides: they hold it by friction without the platform.
      ++two_pads;
      EXPECT_TRUE(objects_balance_without(scene, data, stance, *bottom, mu, K));
    }
  }
  EXPECT_EQ(one_pad, 2);  // arm 1's first pad on platform A, arm 2's last one on platform B
  EXPECT_EQ(two_pads, 1);
}

}  // namespace
}  // namespace stanceplan
