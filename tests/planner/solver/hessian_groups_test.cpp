// The finite-difference Hessian differences several configuration columns per gradient evaluation
// and gives Ipopt only the entries that can be nonzero (planner/solver/hessian_groups.h). Checked
// on every scenario's initial stance at a random point near its start: the sparse, grouped Hessian
// equals the dense one differenced column by column (computed here from the program's exact
// gradient), every entry the dense one has outside the declared structure is zero, and the groups
// are fewer than the columns.
#include <gtest/gtest.h>

#include <memory>
#include <random>
#include <string>

#include "planner/io/scenario.h"
#include "planner/solver/hessian_groups.h"
#include "planner/solver/posture_nlp.h"
#include "tests/support/lagrangian.h"
#include "tests/support/paths.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

// The lambda-lambda block is exact (not differenced): the reference takes it from the program.
Eigen::MatrixXd dense_from(const PostureNlp& nlp, const std::vector<double>& values) {
  std::vector<int> rows(values.size()), cols(values.size());
  nlp.hessian_structure(rows.data(), cols.data());
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(nlp.n(), nlp.n());
  for (size_t k = 0; k < values.size(); ++k) {
    EXPECT_GE(rows[k], cols[k]) << "lower triangle only";
    H(rows[k], cols[k]) = values[k];
  }
  return H;
}

struct Outcome {
  int groups = 0, nq = 0, entries = 0, dense_entries = 0;
};

Outcome check_scenario(const std::string& file) {
  Scenario s = load_scenario(test::source_path("scenarios/" + file));
  s.solver.hessian = HessianMode::FiniteDifference;  // the differenced Hessian (the analytic one
                                                     // is the default: analytic_hessian_test.cpp)
  const PostureRequest request = s.loaded_request(s.initial_stance, s.initial_configuration);
  PostureNlp nlp(s.scene, request, s.solver, {});  // no collision rows
  const int n = nlp.n(), nq = nlp.layout().nq;

  const test::LagrangianPoint point = test::random_lagrangian_point(nlp, 7, 0.02);
  const Eigen::VectorXd& x = point.x;
  const Eigen::VectorXd& y = point.y;
  const double obj_factor = point.obj_factor;

  std::vector<double> values(size_t(nlp.hessian_nnz()));
  nlp.hessian_values(x.data(), true, obj_factor, y.data(), values.data());
  const Eigen::MatrixXd H_sparse = dense_from(nlp, values);

  // Reference: one column per evaluation, forward differences of the same gradient.
  const Eigen::VectorXd g0 = test::lagrangian_gradient(nlp, x, obj_factor, y);
  Eigen::MatrixXd H(n, nq);
  for (int k = 0; k < nq; ++k) {
    Eigen::VectorXd xk = x;
    const double h = 1e-7 * std::max(1.0, std::abs(x[k]));
    xk[k] += h;
    H.col(k) = (test::lagrangian_gradient(nlp, xk, obj_factor, y) - g0) / h;
  }
  double scale = 0.0;
  for (int j = 0; j < nq; ++j)
    for (int i = j; i < n; ++i) scale = std::max(scale, std::abs(H(i, j)));
  Outcome out;
  out.nq = nq;
  out.groups = int(nlp.hessian_groups().groups.size());
  out.entries = nlp.hessian_nnz();
  out.dense_entries = n * (n + 1) / 2;
  for (int j = 0; j < nq; ++j)
    for (int i = j; i < n; ++i) {
      const double expected = i < nq ? 0.5 * (H(i, j) + H(j, i)) : H(i, j);
      EXPECT_NEAR(H_sparse(i, j), expected, 1e-5 * scale)
          << file << ": entry (" << i << ", " << j << ")";
    }
  return out;
}

class EveryScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(EveryScenario, GroupedSparseHessianEqualsColumnByColumn) {
  const Outcome o = check_scenario(GetParam());
  EXPECT_LT(o.groups, o.nq) << "some columns share an evaluation";
  EXPECT_LT(o.entries, o.dense_entries) << "some entries are structural zeros";
  std::printf("%s: %d evaluations for %d columns, %d of %d entries\n", GetParam().c_str(), o.groups,
              o.nq, o.entries, o.dense_entries);
}

INSTANTIATE_TEST_SUITE_P(HessianGroups, EveryScenario,
                         ::testing::Values("humanoid_walk.yaml", "humanoid_sit_desk.yaml",
                                           "hand_ball_rotate.yaml", "hand_pen_regrasp.yaml",
                                           "dual_arm_cylinder.yaml", "two_humanoids_table.yaml",
                                           "humanoid_climb_on_robot.yaml"),
                         [](const auto& info) {
                           std::string name = info.param.substr(0, info.param.find('.'));
                           return name;
                         });

// Two columns that move a common row cannot both be read in one evaluation unless the entry comes
// back from its mirror: a hand-made pattern where columns 0 and 1 share row 2 (a lambda row).
TEST(HessianGroups, ColumnsSharingAForceRowGetTheirOwnEvaluations) {
  const int n = 3, nq = 2;
  std::vector<char> pattern(size_t(n * nq), 0);
  pattern[0 * n + 2] = 1;  // column 0 moves row 2
  pattern[1 * n + 2] = 1;  // column 1 moves row 2
  const HessianGroups g = make_hessian_groups(pattern, n, nq);
  EXPECT_EQ(g.groups.size(), 2u);
  EXPECT_TRUE(g.readable(2, 0));
  EXPECT_TRUE(g.readable(2, 1));
  // Without the shared row, the two (uncoupled) columns share one evaluation.
  pattern[1 * n + 2] = 0;
  const HessianGroups h = make_hessian_groups(pattern, n, nq);
  EXPECT_EQ(h.groups.size(), 1u);
}

// The structure is measured on a generic request, so it is the same for every request of one
// shape (HessianCache hands it to all of them): two soles on the floor at fixed placements, one
// at angle 0 (where sin = 0 once hid terms of E12-E13), the other at 0.3 rad.
TEST(HessianGroups, TheStructureDoesNotDependOnAFixedPlacementsAngle) {
  const Scene scene = test::humanoid_scene("flat_ground");
  auto nlp_at = [&](double theta) {
    PostureRequest r;
    r.contacts = {test::task(scene, "robot/l_sole", "env/floor"),
                  test::task(scene, "robot/r_sole", "env/floor")};
    r.contacts[0].placement = Placement{0.0, 0.1, theta};
    r.contacts[1].placement = Placement{0.0, -0.1, theta};
    r.q_init = test::standing_configuration(scene);
    return std::make_unique<PostureNlp>(scene, r, SolverOptions{}, std::vector<int>{});
  };
  const auto zero = nlp_at(0.0), turned = nlp_at(0.3);
  ASSERT_EQ(zero->hessian_nnz(), turned->hessian_nnz());
  std::vector<int> rows0(size_t(zero->hessian_nnz())), cols0(rows0.size());
  std::vector<int> rows1(rows0.size()), cols1(rows0.size());
  zero->hessian_structure(rows0.data(), cols0.data());
  turned->hessian_structure(rows1.data(), cols1.data());
  EXPECT_EQ(rows0, rows1);
  EXPECT_EQ(cols0, cols1);
  EXPECT_EQ(zero->hessian_groups().groups, turned->hessian_groups().groups);
  EXPECT_EQ(zero->hessian_groups().pattern, turned->hessian_groups().pattern);
}

}  // namespace
}  // namespace stanceplan
