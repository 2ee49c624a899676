// The finite-difference Hessian differences several configuration columns per gradient evaluation
// when their entities share no contact (planner/solver/hessian_groups.h). Checked on the table
// carry (two humanoids, each touching only the table and the floor): the grouped Hessian equals
// the one differenced column by column, computed here from the program's exact gradient, and a
// single robot keeps one column per evaluation.
#include <gtest/gtest.h>

#include <random>

#include "planner/io/scenario.h"
#include "planner/solver/hessian_groups.h"
#include "planner/solver/posture_nlp.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

const Scenario& table_scenario() {
  static const Scenario s = load_scenario(test::source_path("scenarios/two_humanoids_table.yaml"));
  return s;
}

// Gradient of obj_factor f + y^T g at x, every family but collision (which gets no curvature).
Eigen::VectorXd lagrangian_gradient(PostureNlp& nlp, const Eigen::VectorXd& x, double obj_factor,
                                    const Eigen::VectorXd& y) {
  Eigen::VectorXd grad(nlp.n());
  nlp.objective_gradient(x.data(), true, grad.data());
  return obj_factor * grad + nlp.dense_jacobian(x.data(), false).transpose() * y;
}

TEST(HessianGroups, TwoRobotsCarryingATableShareEvaluationsAndKeepTheirEntries) {
  const Scenario& s = table_scenario();
  const PostureRequest request = s.loaded_request(s.initial_stance, s.initial_configuration);
  PostureNlp nlp(s.scene, request, s.solver, {});  // no collision rows
  const int n = nlp.n(), nq = nlp.layout().nq;

  const HessianGroups groups =
      make_hessian_groups(s.scene.system, nlp.state().constants, nlp.layout());
  const System& system = s.scene.system;
  const int robot = system.find_entity(system.entity(0).name);
  // The two robots share evaluations; the table (touching both) has its own.
  EXPECT_EQ(groups.groups.size(),
            size_t(system.entity(robot).nq() + system.entity(system.find_entity("table")).nq()));
  EXPECT_LT(int(groups.groups.size()), nq);

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Eigen::VectorXd x(n);
  nlp.starting_point(x.data());
  for (int i = 0; i < nq; ++i) x[i] += 0.02 * u(rng);
  Eigen::VectorXd y(nlp.m());
  for (int i = 0; i < nlp.m(); ++i) y[i] = u(rng);
  const double obj_factor = 0.7;

  std::vector<double> values(size_t(nlp.hessian_nnz()));
  nlp.hessian_values(x.data(), true, obj_factor, y.data(), values.data());

  // Reference: one column per evaluation, forward differences of the same gradient.
  const Eigen::VectorXd g0 = lagrangian_gradient(nlp, x, obj_factor, y);
  Eigen::MatrixXd H(n, nq);
  for (int k = 0; k < nq; ++k) {
    Eigen::VectorXd xk = x;
    const double h = 1e-7 * std::max(1.0, std::abs(x[k]));
    xk[k] += h;
    H.col(k) = (lagrangian_gradient(nlp, xk, obj_factor, y) - g0) / h;
  }
  double scale = 0.0;
  for (int j = 0; j < nq; ++j)
    for (int i = j; i < n; ++i) scale = std::max(scale, std::abs(H(i, j)));
  int k = 0, compared = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j <= i; ++j, ++k) {
      if (j >= nq) continue;  // lambda-lambda: exact, not differenced
      const double expected = i < nq ? 0.5 * (H(i, j) + H(j, i)) : H(i, j);
      ASSERT_NEAR(values[size_t(k)], expected, 1e-5 * scale) << "entry (" << i << ", " << j << ")";
      ++compared;
    }
  EXPECT_GT(compared, nq * nq / 2);
}

TEST(HessianGroups, OneRobotKeepsOneColumnPerEvaluation) {
  const Scenario s = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  const PostureRequest request = s.loaded_request(s.initial_stance, s.initial_configuration);
  PostureNlp nlp(s.scene, request, s.solver, {});
  const HessianGroups groups =
      make_hessian_groups(s.scene.system, nlp.state().constants, nlp.layout());
  ASSERT_EQ(int(groups.groups.size()), nlp.layout().nq);
  for (int c = 0; c < nlp.layout().nq; ++c) {
    EXPECT_FALSE(groups.shared(c));
    EXPECT_EQ(groups.groups[size_t(c)], std::vector<int>{c});
  }
}

}  // namespace
}  // namespace stanceplan
