// Starting forces balanced at the starting configuration (planner/solver/force_balance.h): they
// meet E16-E17, stay inside the cones, are the barrier program's minimiser (stationary along every
// balanced direction), leave the start alone when no force can hold the body, and make a warm start
// from a configuration alone take fewer iterations than the even shares.
#include <gtest/gtest.h>

#include <random>

#include "planner/io/scenario.h"
#include "planner/solver/blocks/blocks.h"
#include "planner/solver/force_balance.h"
#include "planner/solver/posture_nlp.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/paths.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

class ForceBalance : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = new Scene(test::humanoid_scene("wall")); }
  static void TearDownTestSuite() { delete scene_; }
  static Scene* scene_;

  // Feet on the floor and both palms on the wall (the solver benchmark's 4 contacts).
  static PostureRequest four_contacts() {
    PostureRequest r;
    r.contacts = {test::task(*scene_, "robot/l_sole", "env/floor"),
                  test::task(*scene_, "robot/r_sole", "env/floor"),
                  test::task(*scene_, "robot/r_palm", "env/wall"),
                  test::task(*scene_, "robot/l_palm", "env/wall")};
    r.q_init = test::standing_configuration(*scene_);
    const Model& m = *scene_->system.entity(0).model;
    for (const char* side : {"r_", "l_"}) {
      r.q_init[7 + m.find_dof(std::string(side) + "shoulder_p")] = -1.4;
      r.q_init[7 + m.find_dof(std::string(side) + "wrist_p")] = -1.2;
    }
    r.q_ref = r.q_init;
    return r;
  }
  // The request started from `solution`'s configuration moved 2 cm (no force guesses).
  static PostureRequest near(PostureRequest r, const PostureResult& solution) {
    r.q_init = solution.q;
    r.q_init[0] += 0.02;
    r.q_ref = solution.q;
    return r;
  }
  // E23 + E24 at the state's x minus the barrier: what balance_starting_forces minimises.
  static double barrier_cost(NlpState& state, const Eigen::VectorXd& x, const Eigen::VectorXd& even,
                             double mu) {
    state.set_x(x.data());
    state.ensure_torque_values();
    const int nq = state.layout.nq;
    double cost = state.options.w_force * x.tail(x.size() - nq).squaredNorm();
    for (const Eigen::VectorXd& tau : state.tau) cost += state.options.w_torque * tau.squaredNorm();
    for (int k = 0; k < even.size(); ++k) cost -= mu * even[k] * std::log(x[nq + k]);
    return cost;
  }
};
Scene* ForceBalance::scene_ = nullptr;

// The even shares leave the robot unbalanced at a solved configuration; the balanced forces meet
// every equilibrium row, stay strictly inside the cones and are the barrier program's minimiser:
// along every direction that keeps the balance the cost's slope is zero and it curves upward.
TEST_F(ForceBalance, BalancesTheRobotInsideTheConesAtLeastCost) {
  const PostureSolver solver(*scene_, SolverOptions{});
  const PostureResult solution = solver.solve(four_contacts());
  ASSERT_EQ(solution.status, PostureStatus::Solved) << solution.message;
  const PostureRequest r = near(four_contacts(), solution);
  const SolverOptions options;
  const NlpLayout layout(*scene_, r, options);
  NlpState state(*scene_, r, options, layout);
  Eigen::VectorXd x = make_starting_point(state);
  const EquilibriumBlock equilibrium(state, 0);
  Eigen::VectorXd g(6);
  equilibrium.evaluate(state, g);
  EXPECT_GT(g.cwiseAbs().maxCoeff(), 0.1);  // even shares: far from balanced
  const Eigen::VectorXd even = x.tail(layout.n - layout.nq);

  const ForceBalanceResult b = balance_starting_forces(state, x);
  ASSERT_TRUE(b.balanced) << b.residual;
  EXPECT_LE(b.iterations, 20);
  equilibrium.evaluate(state, g);
  EXPECT_LE(g.cwiseAbs().maxCoeff(), 1e-9);
  const Eigen::VectorXd lambda = x.tail(layout.n - layout.nq);
  EXPECT_GT(lambda.minCoeff(), 0.0);

  // Balanced directions: the null space of the equilibrium rows' force columns.
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(6, layout.n);
  equilibrium.jacobian(state, J);
  const Eigen::MatrixXd A = J.rightCols(lambda.size());
  const Eigen::MatrixXd P = Eigen::MatrixXd::Identity(lambda.size(), lambda.size()) -
                            A.transpose() * (A * A.transpose()).ldlt().solve(A);
  std::mt19937 rng(7);
  std::normal_distribution<double> normal;
  const double base = barrier_cost(state, x, even, b.mu);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd d(lambda.size());
    for (int k = 0; k < d.size(); ++k) d[k] = normal(rng);
    d = P * d;
    d *= 1e-3 * lambda.minCoeff() / d.cwiseAbs().maxCoeff();  // stays inside the cones
    Eigen::VectorXd plus = x, minus = x;
    plus.tail(d.size()) += d;
    minus.tail(d.size()) -= d;
    const double up = barrier_cost(state, plus, even, b.mu);
    const double down = barrier_cost(state, minus, even, b.mu);
    const double curvature = up + down - 2.0 * base;
    EXPECT_GT(curvature, 0.0) << "trial " << trial;
    EXPECT_LE(std::abs(up - down), 1e-4 * curvature + 1e-12 * std::abs(base))
        << "trial " << trial;  // slope / curvature ~ 0
  }
}

// A humanoid touching the wall with one palm only cannot be held (the wall's normal is
// horizontal, friction needs a normal force that nothing balances): the start is left alone.
TEST_F(ForceBalance, LeavesTheEvenSharesWhenNoForceCanHoldTheBody) {
  PostureRequest r;
  r.contacts = {test::task(*scene_, "robot/r_palm", "env/wall")};
  r.q_init = four_contacts().q_init;
  const SolverOptions options;
  const NlpLayout layout(*scene_, r, options);
  NlpState state(*scene_, r, options, layout);
  Eigen::VectorXd x = make_starting_point(state);
  const Eigen::VectorXd before = x;
  const ForceBalanceResult b = balance_starting_forces(state, x);
  EXPECT_FALSE(b.balanced);
  EXPECT_GT(b.residual, 1e-3);
  EXPECT_EQ(x, before);  // bit for bit
}

// Every scenario's initial stance at its initial configuration: balanced (bilateral handles of the
// table carry included) and bit for bit the same when called twice.
TEST(ForceBalanceScenarios, EveryInitialStanceIsBalancedTheSameWayTwice) {
  for (const char* file : {"humanoid_walk.yaml", "humanoid_sit_desk.yaml", "hand_ball_rotate.yaml",
                           "hand_pen_regrasp.yaml", "dual_arm_cylinder.yaml",
                           "two_humanoids_table.yaml", "humanoid_climb_on_robot.yaml"}) {
    const Scenario scenario = load_scenario(test::source_path(std::string("scenarios/") + file));
    const PostureRequest r =
        scenario.loaded_request(scenario.initial_stance, scenario.initial_configuration);
    const SolverOptions options = scenario.solver;
    const NlpLayout layout(scenario.scene, r, options);
    Eigen::VectorXd first, second;
    for (Eigen::VectorXd* out : {&first, &second}) {
      NlpState state(scenario.scene, r, options, layout);
      *out = make_starting_point(state);
      const ForceBalanceResult b = balance_starting_forces(state, *out);
      EXPECT_TRUE(b.balanced) << file << ": residual " << b.residual;
    }
    EXPECT_EQ(first, second) << file;
  }
}

// From a configuration alone near a 4-contact solution: fewer Ipopt iterations from the balanced
// forces than from the even shares (bench/solver_bench measures 5 against 9).
TEST_F(ForceBalance, AConfigurationOnlyWarmStartTakesFewerIterations) {
  const PostureSolver solver(*scene_, SolverOptions{});
  const PostureResult solution = solver.solve(four_contacts());
  ASSERT_EQ(solution.status, PostureStatus::Solved) << solution.message;
  const PostureRequest r = near(four_contacts(), solution);
  SolverOptions even_shares;
  even_shares.balance_starting_forces = false;
  const PostureResult balanced = solver.solve(r);
  const PostureResult even = PostureSolver(*scene_, even_shares).solve(r);
  ASSERT_EQ(balanced.status, PostureStatus::Solved) << balanced.message;
  ASSERT_EQ(even.status, PostureStatus::Solved) << even.message;
  EXPECT_LT(balanced.iterations, even.iterations);
  EXPECT_LE(balanced.iterations, 6);
}

}  // namespace
}  // namespace stanceplan
