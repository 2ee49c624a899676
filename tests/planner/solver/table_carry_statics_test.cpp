// Multi-entity statics (docs/METHOD.md section 4, E16-E18) with two floating robots and an object
// between them: the initial stance of scenarios/two_humanoids_table.yaml, four feet on the floor
// and four palms on the table's handles (bilateral). Each palm force acts BY the table ON the robot
// (s1 = palm), so the table receives the opposite of all four, from both robots; each robot's
// torques carry its own palms' loads. Everything is re-checked here from forward kinematics alone:
// equilibrium sums and torques by virtual work (central differences of point positions and of the
// weight's potential), never from the solver's code.
#include <gtest/gtest.h>

#include "planner/io/scenario.h"
#include "planner/model/kinematics.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

class TableCarry : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scenario_ =
        new Scenario(load_scenario(test::source_path("scenarios/two_humanoids_table.yaml")));
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
  static const Surface& s1_of(const VertexForce& f) {
    return scenario_->scene.surfaces.get(request_->contacts[f.contact].contact.s1);
  }
  static bool on_palm(const VertexForce& f, int robot) {
    const Contact& c = request_->contacts[f.contact].contact;
    return c.s1.entity == robot && c.s2.entity == entity("table");
  }
  static Eigen::VectorXd entity_q(int e) {
    return result_->q.segment(system().offset(e), system().entity(e).nq());
  }
  static Eigen::Vector3d com(int e, const Eigen::VectorXd& q_e) {
    ModelData data(system().entity(e));
    forward_kinematics(system().entity(e), q_e, data);
    return center_of_mass(system().entity(e), data);
  }
  // World position of the s1 vertex a force acts at, for the robot's configuration q_e.
  static Eigen::Vector3d force_point(int e, const VertexForce& f, const Eigen::VectorXd& q_e) {
    ModelData data(system().entity(e));
    forward_kinematics(system().entity(e), q_e, data);
    return data.T_WL[s1_of(f).link] * s1_of(f).vertex_L(f.vertex);
  }
  // E18 by virtual work, joint by joint with the base held still: tau = -sum J_p^T f over the
  // loads the robot receives as s1 (feet, and palms scaled by `palm_sign`) + dV/dtheta, V = -m g.c.
  static Eigen::VectorXd torques_by_differences(int robot, double palm_sign) {
    const Entity& r = system().entity(robot);
    const Eigen::VectorXd q_e = entity_q(robot);
    const double m = r.model->total_mass, h = 1e-6;
    Eigen::VectorXd tau = Eigen::VectorXd::Zero(r.model->num_dofs());
    for (int k = 0; k < tau.size(); ++k) {
      Eigen::VectorXd plus = q_e, minus = q_e;
      plus[r.first_dof() + k] += h;
      minus[r.first_dof() + k] -= h;
      for (const VertexForce& f : result_->forces) {
        if (request_->contacts[f.contact].contact.s1.entity != robot) continue;
        const double sign = on_palm(f, robot) ? palm_sign : 1.0;
        tau[k] -= sign * f.force_W.dot(force_point(robot, f, plus) - force_point(robot, f, minus)) /
                  (2 * h);
      }
      tau[k] += -m * gravity().dot(com(robot, plus) - com(robot, minus)) / (2 * h);
    }
    return tau;
  }

  static Scenario* scenario_;
  static PostureRequest* request_;
  static PostureResult* result_;
};
Scenario* TableCarry::scenario_ = nullptr;
PostureRequest* TableCarry::request_ = nullptr;
PostureResult* TableCarry::result_ = nullptr;

TEST_F(TableCarry, TheTableBalancesOnTheFourPalmsOfBothRobots) {
  ASSERT_EQ(result_->status, PostureStatus::Solved) << result_->message;
  const int t = entity("table");
  const double m = system().entity(t).model->total_mass;
  ASSERT_NEAR(m, 6.0, 1e-12);
  const Eigen::Vector3d c_W = com(t, entity_q(t));
  Eigen::Vector3d force = m * gravity(), moment = Eigen::Vector3d::Zero(), flipped = m * gravity();
  int palm_forces = 0;
  for (const VertexForce& f : result_->forces) {
    if (request_->contacts[f.contact].contact.s2.entity != t) continue;
    ++palm_forces;
    force -= f.force_W;                             // E16: the table is s2, it receives -f
    moment += (f.point_W - c_W).cross(-f.force_W);  // E17 about its centre of mass
    flipped += f.force_W;
  }
  EXPECT_EQ(palm_forces, 16);  // 4 palms x 4 vertices, from both robots
  EXPECT_LT(force.norm(), 1e-6 * m * gravity().norm()) << force.transpose();
  EXPECT_LT(moment.norm(), 1e-6 * m * gravity().norm() * 1.0) << moment.transpose();  // 1 m lever
  EXPECT_NEAR(flipped.norm(), 2 * m * gravity().norm(), 1e-5);  // the wrong sign doubles the weight
}

TEST_F(TableCarry, BothRobotsCarryAShareOfTheTable) {
  ASSERT_EQ(result_->status, PostureStatus::Solved) << result_->message;
  const double weight = system().entity(entity("table")).model->total_mass * gravity().norm();
  double total = 0.0;
  for (const char* name : {"r1", "r2"}) {
    double down = 0.0;  // the table pulls each robot's palms down (the force on s1 points to -z)
    for (const VertexForce& f : result_->forces)
      if (on_palm(f, entity(name))) down -= f.force_W.z();
    EXPECT_GT(down, 0.2 * weight) << name;
    total += down;
  }
  EXPECT_NEAR(total, weight, 1e-6 * weight);
}

TEST_F(TableCarry, EachRobotBalancesItsWeightItsFeetAndItsPalms) {
  ASSERT_EQ(result_->status, PostureStatus::Solved) << result_->message;
  for (const char* name : {"r1", "r2"}) {
    const int r = entity(name);
    const double m = system().entity(r).model->total_mass;
    const Eigen::Vector3d c_W = com(r, entity_q(r));
    Eigen::Vector3d force = m * gravity(), moment = Eigen::Vector3d::Zero();
    for (const VertexForce& f : result_->forces) {
      if (request_->contacts[f.contact].contact.s1.entity != r) continue;
      force += f.force_W;  // the robot is s1 of its feet and palms
      moment += (f.point_W - c_W).cross(f.force_W);
    }
    EXPECT_LT(force.norm(), 1e-6 * m * gravity().norm()) << name << ": " << force.transpose();
    EXPECT_LT(moment.norm(), 1e-6 * m * gravity().norm() * 1.0)
        << name << ": " << moment.transpose();
  }
}

TEST_F(TableCarry, EachRobotsTorquesIncludeTheTablesPullOnItsPalms) {
  ASSERT_EQ(result_->status, PostureStatus::Solved) << result_->message;
  for (const char* name : {"r1", "r2"}) {
    const int r = entity(name);
    const Eigen::VectorXd& tau = result_->torques.at(r);
    ASSERT_EQ(tau.size(), 32) << name;
    const Eigen::VectorXd expected = torques_by_differences(r, +1.0);
    EXPECT_LT((tau - expected).cwiseAbs().maxCoeff(), 1e-4)
        << name << "\nsolver:   " << tau.transpose() << "\nexpected: " << expected.transpose();
    // Without the palms' loads, or with them reversed, the arms' torques differ by newton-metres.
    EXPECT_GT((tau - torques_by_differences(r, 0.0)).cwiseAbs().maxCoeff(), 1.0) << name;
    EXPECT_GT((tau - torques_by_differences(r, -1.0)).cwiseAbs().maxCoeff(), 2.0) << name;
  }
}

}  // namespace
}  // namespace stanceplan
