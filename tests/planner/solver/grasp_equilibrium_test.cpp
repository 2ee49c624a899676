// Multi-entity statics (docs/METHOD.md section 4, E16-E18): a ball held by the four fingertips of
// the fixed hand (scenarios/hand_ball_rotate.yaml). The solver's forces act BY the ball ON the
// fingertips, so the ball receives their opposites: its equilibrium (E16-E17 with the sign flip of
// the larger surface) and the hand's torques (E18, the reaction of the ball on the fingers plus the
// fingers' weight) are checked here against finite differences of forward kinematics alone.
#include <gtest/gtest.h>

#include "planner/io/scenario.h"
#include "planner/model/kinematics.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

class Grasp : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scenario_ = new Scenario(load_scenario(test::source_path("scenarios/hand_ball_rotate.yaml")));
    request_ = new PostureRequest(
        scenario_->loaded_request(scenario_->initial_stance, scenario_->initial_configuration));
    result_ =
        new PostureResult(PostureSolver(scenario_->scene, scenario_->solver).solve(*request_));
  }
  static void TearDownTestSuite() {
    delete result_;
    delete request_;
    delete scenario_;
  }

  static const System& system() { return scenario_->scene.system; }
  static int entity(const std::string& name) { return system().find_entity(name); }
  static Eigen::Vector3d gravity() { return scenario_->scene.gravity; }

  // World position of the s1 vertex a force acts at, for the hand's joints `theta`.
  static Eigen::Vector3d force_point(const VertexForce& f, const Eigen::VectorXd& theta) {
    const Entity& hand = system().entity(entity("hand"));
    ModelData data(hand);
    forward_kinematics(hand, theta, data);
    const Surface& s1 = scenario_->scene.surfaces.get(request_->contacts[f.contact].contact.s1);
    return data.T_WL[s1.link] * s1.vertex_L(f.vertex);
  }
  // Potential energy of the hand's weight: -m g . c(theta).
  static double weight_potential(const Eigen::VectorXd& theta) {
    const Entity& hand = system().entity(entity("hand"));
    ModelData data(hand);
    forward_kinematics(hand, theta, data);
    return -hand.model->total_mass * gravity().dot(center_of_mass(hand, data));
  }
  // E18 by virtual work, central differences: tau = -sum J_p^T f (the ball's push on the
  // fingertips, with `contact_sign` = +1) + dV/dtheta (holding the fingers up).
  static Eigen::VectorXd torques_by_differences(double contact_sign) {
    const int h_entity = entity("hand");
    const Eigen::VectorXd theta =
        result_->q.segment(system().offset(h_entity), system().entity(h_entity).nq());
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(theta.size());
    const double h = 1e-6;
    for (int k = 0; k < theta.size(); ++k) {
      Eigen::VectorXd plus = theta, minus = theta;
      plus[k] += h;
      minus[k] -= h;
      for (const VertexForce& f : result_->forces)
        tau[k] -=
            contact_sign * f.force_W.dot(force_point(f, plus) - force_point(f, minus)) / (2 * h);
      tau[k] += (weight_potential(plus) - weight_potential(minus)) / (2 * h);
    }
    return tau;
  }

  static Scenario* scenario_;
  static PostureRequest* request_;
  static PostureResult* result_;
};
Scenario* Grasp::scenario_ = nullptr;
PostureRequest* Grasp::request_ = nullptr;
PostureResult* Grasp::result_ = nullptr;

TEST_F(Grasp, TheFourFingertipsHoldTheBall) {
  ASSERT_EQ(result_->status, PostureStatus::Solved) << result_->message;
  ASSERT_EQ(result_->forces.size(), 16u);  // 4 contacts x 4 pad vertices
  std::vector<double> normal(4, 0.0);
  for (const VertexForce& f : result_->forces) {
    const Contact& c = request_->contacts[f.contact].contact;
    const Eigen::Vector3d n_W = system_kinematics(system(), result_->q)[c.s1.entity]
                                    .T_WL[scenario_->scene.surfaces.get(c.s1).link]
                                    .linear() *
                                scenario_->scene.surfaces.get(c.s1).normal_L();
    normal[f.contact] -= f.force_W.dot(n_W);  // the ball pushes the pad back along -n of the pad
  }
  for (int c = 0; c < 4; ++c) EXPECT_GT(normal[c], 1e-3) << "contact " << c << " carries no load";
}

TEST_F(Grasp, ForcesOnTheBallBalanceItsWeight) {
  ASSERT_EQ(result_->status, PostureStatus::Solved) << result_->message;
  const int b = entity("ball");
  const double m = system().entity(b).model->total_mass;
  ASSERT_NEAR(m, 0.1, 1e-12);
  const Eigen::Vector3d c_W =
      result_->q.segment<3>(system().offset(b));  // the ball's CoM is its origin
  Eigen::Vector3d force = m * gravity(), moment = Eigen::Vector3d::Zero();
  for (const VertexForce& f : result_->forces) {
    force -= f.force_W;  // E16: the ball is s2 of every contact, it receives -f
    moment += (f.point_W - c_W).cross(-f.force_W);  // E17 about the CoM (gravity has no moment)
  }
  EXPECT_LT(force.norm(), 1e-6) << force.transpose();    // N: Ipopt's constraint tolerance
  EXPECT_LT(moment.norm(), 1e-6) << moment.transpose();  // N m: Ipopt's constraint tolerance
  // With the wrong sign the residual would be twice the weight.
  Eigen::Vector3d flipped = m * gravity();
  for (const VertexForce& f : result_->forces) flipped += f.force_W;
  EXPECT_NEAR(flipped.norm(), 2 * m * gravity().norm(), 1e-6);
}

TEST_F(Grasp, HandTorquesIncludeTheBallsReaction) {
  ASSERT_EQ(result_->status, PostureStatus::Solved) << result_->message;
  const Eigen::VectorXd& tau = result_->torques.at(entity("hand"));
  ASSERT_EQ(tau.size(), 24);
  const Eigen::VectorXd expected = torques_by_differences(+1.0);
  EXPECT_LT((tau - expected).cwiseAbs().maxCoeff(), 1e-5)
      << "solver:   " << tau.transpose() << "\nexpected: " << expected.transpose();
  // The reaction is not negligible: leaving it out, or counting it with the wrong sign, would be
  // caught by the comparison above.
  const Eigen::VectorXd weight_only = torques_by_differences(0.0);
  const Eigen::VectorXd wrong_sign = torques_by_differences(-1.0);
  EXPECT_GT((tau - weight_only).cwiseAbs().maxCoeff(), 1e-2);
  EXPECT_GT((tau - wrong_sign).cwiseAbs().maxCoeff(), 2e-2);
}

}  // namespace
}  // namespace stanceplan
