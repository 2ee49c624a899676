// Solver faults through the public solver API: a NaN in the initial guess or the reference, a
// degenerate configuration (zero quaternion, joints far past their limits, the robot 1 km up) and
// the iteration limit each end as a status with its reason, never an exception, a crash or a hang,
// and no non-finite number is ever part of a result marked solved.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <limits>

#include "planner/solver/posture_solver.h"
#include "planner/solver/solver_pool.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

class SolverFaults : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = new Scene(test::humanoid_scene("flat_ground")); }
  static void TearDownTestSuite() { delete scene_; }

  // Both soles on the floor, every contact loaded, from the standing configuration.
  static PostureRequest standing() {
    PostureRequest request;
    request.contacts = {test::task(*scene_, "robot/l_sole", "env/floor"),
                        test::task(*scene_, "robot/r_sole", "env/floor")};
    request.q_init = test::standing_configuration(*scene_);
    return request;
  }
  static int dof(const std::string& joint) {
    return 7 + scene_->system.entity(0).model->find_dof(joint);
  }

  // A solved result is finite and keeps a unit quaternion; any other result says why.
  static void expect_sound(const PostureResult& r) {
    if (r.status == PostureStatus::Solved) {
      EXPECT_EQ(r.non_finite_part(), "");
      EXPECT_NEAR(r.q.segment<4>(3).norm(), 1.0, 1e-9);
    } else {
      EXPECT_FALSE(r.message.empty());
    }
  }
  static Scene* scene_;
};
Scene* SolverFaults::scene_ = nullptr;

TEST_F(SolverFaults, ANanInTheInitialGuessIsAFailureWithItsReason) {
  const PostureSolver solver(*scene_, {});
  PostureRequest request = standing();
  request.q_init[dof("l_knee_p")] = std::numeric_limits<double>::quiet_NaN();
  const PostureResult r = solver.solve(request);
  EXPECT_EQ(r.status, PostureStatus::NumericalFailure);
  EXPECT_EQ(r.message, "the initial guess is not finite (q_init[" +
                           std::to_string(dof("l_knee_p")) + "] = nan)");
  EXPECT_EQ(r.q.size(), 0);
  request = standing();
  request.q_ref = request.q_init;
  request.q_ref[2] = std::numeric_limits<double>::infinity();
  EXPECT_EQ(solver.solve(request).message, "the initial guess is not finite (q_ref[2] = inf)");
}

TEST_F(SolverFaults, ANanGuessSentToAWorkerProcessIsAFailureToo) {
  const PostureSolver solver(*scene_, {});
  SolverPool pool(solver, 2);
  std::vector<PostureRequest> requests = {standing(), standing()};
  requests[1].q_init[0] = std::numeric_limits<double>::quiet_NaN();
  const std::vector<PostureResult> results = pool.solve_all(requests);
  ASSERT_EQ(results.size(), 2u);
  EXPECT_EQ(results[0].status, PostureStatus::Solved) << results[0].message;
  EXPECT_EQ(results[1].status, PostureStatus::NumericalFailure);
  EXPECT_EQ(results[1].message, "the initial guess is not finite (q_init[0] = nan)");
}

TEST_F(SolverFaults, AZeroQuaternionGuessIsAFailureWithItsReason) {
  const PostureSolver solver(*scene_, {});
  PostureRequest request = standing();
  request.q_init.segment<4>(3).setZero();
  const PostureResult r = solver.solve(request);
  EXPECT_EQ(r.status, PostureStatus::NumericalFailure);
  EXPECT_EQ(r.message, "the initial guess has a zero base quaternion (entity \"robot\")");
  // A quaternion that is merely not unit is a rotation: it is normalised and solved from.
  request.q_init.segment<4>(3) << 0.5, 0.0, 0.0, 0.0;
  expect_sound(solver.solve(request));
}

TEST_F(SolverFaults, JointsFarPastTheirLimitsAndARobotOneKilometreUpEndAsAStatus) {
  const PostureSolver solver(*scene_, {});
  PostureRequest request = standing();
  for (int k = 7; k < request.q_init.size(); ++k) request.q_init[k] = (k % 2 ? 1e3 : -1e3);
  expect_sound(solver.solve(request));
  request = standing();
  request.q_init[2] = 1000.0;
  expect_sound(solver.solve(request));
}

TEST_F(SolverFaults, TheIterationLimitIsAStatusWithItsReason) {
  SolverOptions options;
  options.max_iterations = 1;
  const PostureSolver solver(*scene_, options);
  PostureRequest request = standing();
  request.q_init[2] = 1.2;  // 27 cm above the floor: one iteration cannot close the contact gap
  const PostureResult r = solver.solve(request);
  EXPECT_EQ(r.status, PostureStatus::IterationLimit);
  EXPECT_THAT(r.message, HasSubstr("Maximum_Iterations_Exceeded"));
  EXPECT_THAT(r.message, HasSubstr("worst violated family: "));
  EXPECT_EQ(r.iterations, 1);
}

}  // namespace
}  // namespace stanceplan
