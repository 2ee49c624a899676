// Warm-started contact forces (ContactTask::force_guess_W): the starting point's cone coefficients
// give back a guessed force inside the friction cone exactly and stay interior for one outside it;
// a solve started at a solution, its configuration and forces, needs fewer iterations than one
// started at its configuration only.
#include <gtest/gtest.h>

#include <algorithm>

#include "planner/solver/posture_nlp.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

class ForceGuess : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = new Scene(test::humanoid_scene("wall")); }
  static void TearDownTestSuite() { delete scene_; }
  static Scene* scene_;

  static PostureRequest standing_request() {
    PostureRequest r;
    r.contacts = {test::task(*scene_, "robot/l_sole", "env/floor"),
                  test::task(*scene_, "robot/r_sole", "env/floor")};
    r.q_init = test::standing_configuration(*scene_);
    return r;
  }
  // The starting point's lambda of the left sole's vertex j (K coefficients).
  static Eigen::VectorXd lambda(const PostureNlp& nlp, const Eigen::VectorXd& x, int j) {
    const ForceBlock& block = nlp.layout().forces[0];
    return x.segment(block.first_column + j * block.per_vertex, block.per_vertex);
  }
  // A request started at a solution: its configuration and, per vertex, its forces.
  static PostureRequest started_at(PostureRequest r, const PostureResult& solution) {
    if (r.q_ref.size() == 0) r.q_ref = r.q_init;  // the same objective (E21) as the solution's
    r.q_init = solution.q;
    for (const VertexForce& f : solution.forces) {
      auto& guess = r.contacts[size_t(f.contact)].force_guess_W;
      guess.resize(size_t(f.vertex) + 1);
      guess[size_t(f.vertex)] = f.force_W;
    }
    return r;
  }
};
Scene* ForceGuess::scene_ = nullptr;

TEST_F(ForceGuess, AForceInsideTheConeIsReproducedExactly) {
  PostureRequest r = standing_request();
  // Floor normal +z, mu = 1, K = 4: inside while each tangential component along a generator's
  // direction is below half the normal force (lambda_k > 0).
  const std::vector<Eigen::Vector3d> guess = {
      {10.0, -5.0, 80.0}, {0.0, 0.0, 50.0}, {-12.0, 3.0, 60.0}, {4.0, 9.0, 30.0}};
  r.contacts[0].force_guess_W = guess;
  const SolverOptions options;
  PostureNlp nlp(*scene_, r, options, {});
  ASSERT_EQ(nlp.state().frames[0].p.size(), guess.size());
  Eigen::VectorXd x(nlp.n());
  nlp.starting_point(x.data());
  nlp.state().set_x(x.data());  // frames[0].f = sum_k lambda_k U_k (E5)
  for (size_t j = 0; j < guess.size(); ++j) {
    EXPECT_LE((nlp.state().frames[0].f[j] - guess[j]).norm(), 1e-12 * guess[j].norm())
        << "vertex " << j;
    EXPECT_GT(lambda(nlp, x, int(j)).minCoeff(), 1e-3) << "vertex " << j;
  }
}

TEST_F(ForceGuess, AForceOutsideTheConeIsClampedInside) {
  PostureRequest r = standing_request();
  // Sliding (tangential 10 x normal), pulling, zero and mostly tangential forces.
  r.contacts[0].force_guess_W = {
      {100.0, 0.0, 10.0}, {0.0, 0.0, -50.0}, {0.0, 0.0, 0.0}, {0.0, 30.0, 20.0}};
  const SolverOptions options;
  PostureNlp nlp(*scene_, r, options, {});
  Eigen::VectorXd x(nlp.n());
  nlp.starting_point(x.data());
  for (int j = 0; j < 4; ++j) {
    const Eigen::VectorXd l = lambda(nlp, x, j);
    EXPECT_GE(l.minCoeff(), 1e-3) << "vertex " << j;
    EXPECT_EQ(l.minCoeff(), 1e-3) << "vertex " << j;  // at least one generator clamped
  }
  // The pulling and the zero force: every coefficient at the floor.
  EXPECT_EQ(lambda(nlp, x, 1), Eigen::VectorXd::Constant(4, 1e-3));
  EXPECT_EQ(lambda(nlp, x, 2), Eigen::VectorXd::Constant(4, 1e-3));
}

// With the solver's Ipopt options the solves started at a solution take 4 and 5 iterations, not
// 2-3: Ipopt pushes every lambda at least 1e-2 off its bound (bound_push, bound_frac), which
// unbalances the statics (1e-2 N at iteration 0), and the adaptive barrier's last steps halve the
// distance to the solution each time. From the configuration alone: 4 and 6. The end point may
// move by a millimetre: the regularising objective is only solved to 1e-4 (a flat optimum).
TEST_F(ForceGuess, ASolveStartedAtASolutionNeedsNoMoreIterationsWithItsForces) {
  const PostureSolver solver(*scene_, SolverOptions{});
  const PostureRequest standing = standing_request();
  const PostureResult stand = solver.solve(standing);
  PostureRequest lifting = standing;  // case 2: the left foot about to leave
  for (int i = 0; i < 2; ++i) lifting.contacts[i].placement = stand.placements[i];
  lifting.contacts[0].loaded = false;
  lifting.q_init = stand.q;
  for (const PostureRequest& r : {standing, lifting}) {
    const PostureResult first = solver.solve(r);
    ASSERT_EQ(first.status, PostureStatus::Solved) << first.message;
    const PostureRequest warm = started_at(r, first);
    PostureRequest configuration_only = warm;
    for (ContactTask& t : configuration_only.contacts) t.force_guess_W.clear();
    const PostureResult with_forces = solver.solve(warm);
    const PostureResult without = solver.solve(configuration_only);
    ASSERT_EQ(with_forces.status, PostureStatus::Solved) << with_forces.message;
    ASSERT_EQ(without.status, PostureStatus::Solved) << without.message;
    EXPECT_LE(with_forces.iterations, 5);
    EXPECT_LE(with_forces.iterations, without.iterations);
    EXPECT_LE((with_forces.q - first.q).lpNorm<Eigen::Infinity>(), 2e-3);
  }
}

}  // namespace
}  // namespace stanceplan
