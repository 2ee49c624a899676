// The analytic Hessian of the Lagrangian (HessianMode::Analytic: planner/solver/hessian_terms.h,
// torque_hessian.h, every block's add_hessian) against central differences of the program's exact
// analytic gradient, column by column over all of x = [q | lambda], on every scenario's initial
// stance in the three uses of the program: every contact loaded with a fixed placement, one
// contact added (case 1: unloaded, free placement inside s2's polygon, pulled to a target by
// obj4), and one contact being removed (case 2: unloaded). Random points near the start (a
// non-unit root quaternion included), random multipliers, a torque weight large enough that the
// torque curvature counts. Also: nothing outside the declared Hessian structure is nonzero.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "planner/io/scenario.h"
#include "planner/solver/posture_nlp.h"
#include "tests/support/lagrangian.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

enum class Use { Realise, Add, Remove };

PostureRequest request_for(const Scenario& s, Use use) {
  PostureRequest request = s.loaded_request(s.initial_stance, s.initial_configuration);
  ContactTask& last = request.contacts.back();
  if (use == Use::Add) {
    last.loaded = false;
    last.placement.reset();
    last.placement_target = Placement{0.02, -0.01, 0.0};
  } else if (use == Use::Remove) {
    request.contacts.front().loaded = false;
  }
  return request;
}

void check(const std::string& file, Use use, unsigned seed) {
  Scenario s = load_scenario(test::source_path("scenarios/" + file));
  s.solver.w_torque = 1e-3;  // make E24's curvature visible next to the constraints'
  s.solver.hessian = HessianMode::Analytic;
  const PostureRequest request = request_for(s, use);
  PostureNlp nlp(s.scene, request, s.solver, {});  // no collision rows
  const int n = nlp.n(), nq = nlp.layout().nq;

  const test::LagrangianPoint point = test::random_lagrangian_point(nlp, seed, 0.03);
  const Eigen::VectorXd& x = point.x;
  const Eigen::VectorXd& y = point.y;
  const double obj_factor = point.obj_factor;

  std::vector<double> values(size_t(nlp.hessian_nnz()));
  nlp.hessian_values(x.data(), true, obj_factor, y.data(), values.data());
  const Eigen::MatrixXd H = nlp.dense_hessian();

  Eigen::MatrixXd H_fd(n, n);
  for (int k = 0; k < n; ++k) {
    const double h = 1e-6 * std::max(1.0, std::abs(x[k]));
    Eigen::VectorXd xp = x, xm = x;
    xp[k] += h;
    xm[k] -= h;
    H_fd.col(k) = (test::lagrangian_gradient(nlp, xp, obj_factor, y) -
                   test::lagrangian_gradient(nlp, xm, obj_factor, y)) /
                  (2.0 * h);
  }
  const double scale = std::max(1.0, H_fd.cwiseAbs().maxCoeff());
  int wrong = 0;
  for (int j = 0; j < n && wrong < 10; ++j)
    for (int i = 0; i < n && wrong < 10; ++i)
      if (std::abs(H(i, j) - H_fd(i, j)) > 1e-6 * scale) {
        ++wrong;
        ADD_FAILURE() << file << " use " << int(use) << ": H(" << i << ", " << j
                      << ") = " << H(i, j) << ", differences give " << H_fd(i, j) << " (nq " << nq
                      << ", scale " << scale << ")";
      }
  EXPECT_TRUE(H.isApprox(H.transpose(), 1e-12)) << file << ": symmetric";

  // Nothing outside the declared structure (lower triangle) is nonzero.
  std::vector<int> rows(values.size()), cols(values.size());
  nlp.hessian_structure(rows.data(), cols.data());
  Eigen::MatrixXd declared = Eigen::MatrixXd::Zero(n, n);
  for (size_t k = 0; k < values.size(); ++k) {
    declared(rows[k], cols[k]) = 1.0;
    EXPECT_EQ(values[k], H(rows[k], cols[k]));
  }
  for (int j = 0; j < n; ++j)
    for (int i = j; i < n; ++i)
      if (declared(i, j) == 0.0) {
        EXPECT_LE(std::abs(H(i, j)), 1e-12 * scale)
            << file << ": undeclared entry (" << i << ", " << j << "), nq " << nq;
      }
}

class AnalyticHessianEveryScenario : public ::testing::TestWithParam<std::string> {};

TEST_P(AnalyticHessianEveryScenario, RealiseAStanceMatchesCentralDifferences) {
  check(GetParam(), Use::Realise, 11);
}
TEST_P(AnalyticHessianEveryScenario, AddAContactMatchesCentralDifferences) {
  check(GetParam(), Use::Add, 12);
}
TEST_P(AnalyticHessianEveryScenario, RemoveAContactMatchesCentralDifferences) {
  check(GetParam(), Use::Remove, 13);
}

INSTANTIATE_TEST_SUITE_P(AnalyticHessian, AnalyticHessianEveryScenario,
                         ::testing::Values("humanoid_walk.yaml", "humanoid_sit_desk.yaml",
                                           "hand_ball_rotate.yaml", "hand_pen_regrasp.yaml",
                                           "dual_arm_cylinder.yaml", "two_humanoids_table.yaml",
                                           "humanoid_climb_on_robot.yaml"),
                         [](const auto& info) {
                           return info.param.substr(0, info.param.find('.'));
                         });

}  // namespace
}  // namespace stanceplan
