// Point contacts in the IK-statics program: the rows of ContactGeometryBlock for a sphere at a
// point of a link (E9 with the centre r above s2's plane; E10-E11 for a fixed placement; no E8,
// E12, E13), the Hessian against central differences of the analytic gradient (tips touched, or
// loaded: the force at c - r z2 in E16-E18), E17's and E18's values computed by hand, solves that
// touch and lean on a wall with a round fingertip, and the refusal of a point s2. The Jacobians
// are in derivatives_test.cpp.
#include <gtest/gtest.h>

#include "planner/model/kinematics.h"
#include "planner/solver/force_balance.h"
#include "planner/solver/posture_nlp.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/lagrangian.h"
#include "tests/support/paths.h"
#include "tests/support/point_tips.h"

namespace stanceplan {
namespace {

class PointContactGeometry : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = new Scene(test::humanoid_scene_with_tips("wall")); }
  static void TearDownTestSuite() { delete scene_; }

  // Both soles loaded at their free placements, the left tip added (case 1: free, pulled to a
  // target) on the wall, the right tip touched at a fixed placement on the floor.
  PostureRequest request() const {
    const Scene& s = *scene_;
    PostureRequest r;
    ContactTask tip = test::task(s, "robot/l_tip", "env/wall", false);
    tip.placement_target = Placement{0.1, -0.2, 0.0};
    ContactTask fixed_tip = test::task(s, "robot/r_tip", "env/floor", false);
    fixed_tip.placement = Placement{0.3, -0.4, 0.7};
    r.contacts = {test::task(s, "robot/l_sole", "env/floor"),
                  test::task(s, "robot/r_sole", "env/floor"), tip, fixed_tip};
    r.q_init = test::standing_configuration(s);
    return r;
  }

  // The world position of a tip's centre (the robot is entity 0, at offset 0 of q).
  static Eigen::Vector3d tip_centre(const Eigen::VectorXd& q, const std::string& id) {
    const Entity& robot = scene_->system.entity(0);
    ModelData data(robot);
    forward_kinematics(robot, q.head(robot.nq()), data);
    const Surface& tip = scene_->surfaces.get(test::surface(*scene_, id));
    return data.T_WL[tip.link] * tip.center_L();
  }

  static Scene* scene_;
};
Scene* PointContactGeometry::scene_ = nullptr;

TEST_F(PointContactGeometry, RowsAreTheCentreAboveThePlaneAndThePlacement) {
  const PostureRequest r = request();
  SolverOptions options;
  PostureNlp nlp(*scene_, r, options, {});
  std::vector<int> geometry_rows;
  for (const auto& block : nlp.blocks())
    if (block->family() == "contact_geometry") geometry_rows.push_back(block->rows());
  EXPECT_EQ(geometry_rows, (std::vector<int>{4, 4, 1, 3}));  // soles, free tip, fixed tip
  Eigen::VectorXd x(nlp.n()), g(nlp.m()), lower(nlp.m()), upper(nlp.m());
  nlp.starting_point(x.data());
  nlp.constraints(x.data(), true, g.data());
  nlp.constraint_bounds(lower.data(), upper.data());
  int fixed_first = -1;
  for (size_t b = 0, seen = 0; b < nlp.blocks().size(); ++b)
    if (nlp.blocks()[b]->family() == "contact_geometry" && seen++ == 3)
      fixed_first = nlp.block_first_row(int(b));
  ASSERT_GE(fixed_first, 0);
  EXPECT_EQ(lower[fixed_first], 0.02);  // E9: the centre one radius above the floor
  EXPECT_EQ(upper[fixed_first], 0.02);
  EXPECT_EQ(lower[fixed_first + 1], 0.3);  // E10-E11: the centre's (x, y) on the floor
  EXPECT_EQ(lower[fixed_first + 2], -0.4);
  // At the standing start the right tip's centre is its height above the floor in E9.
  EXPECT_NEAR(g[fixed_first], tip_centre(r.q_init, "robot/r_tip").z(), 1e-12);
}

// max |H - H_fd| / scale of the analytic Hessian against central differences of the gradient.
double hessian_error(const Scene& scene, const PostureRequest& r, const SolverOptions& options) {
  PostureNlp nlp(scene, r, options, {});
  const test::LagrangianPoint point = test::random_lagrangian_point(nlp, 21, 0.03);
  std::vector<double> values(size_t(nlp.hessian_nnz()));
  nlp.hessian_values(point.x.data(), true, point.obj_factor, point.y.data(), values.data());
  const Eigen::MatrixXd H = nlp.dense_hessian();
  const int n = nlp.n();
  Eigen::MatrixXd H_fd(n, n);
  for (int k = 0; k < n; ++k) {
    const double h = 1e-6 * std::max(1.0, std::abs(point.x[k]));
    Eigen::VectorXd xp = point.x, xm = point.x;
    xp[k] += h;
    xm[k] -= h;
    H_fd.col(k) = (test::lagrangian_gradient(nlp, xp, point.obj_factor, point.y) -
                   test::lagrangian_gradient(nlp, xm, point.obj_factor, point.y)) /
                  (2.0 * h);
  }
  return (H - H_fd).cwiseAbs().maxCoeff() / std::max(1.0, H_fd.cwiseAbs().maxCoeff());
}

class PointContactHessian : public PointContactGeometry,
                            public ::testing::WithParamInterface<bool> {};

// Unloaded tips (the geometry rows), or loaded ones (their force in E16-E17 at c - r z2 too).
TEST_P(PointContactHessian, MatchesCentralDifferences) {
  SolverOptions options;
  options.hessian = HessianMode::Analytic;
  options.w_torque = 1e-3;
  PostureRequest r = request();
  r.contacts[2].loaded = r.contacts[3].loaded = GetParam();
  // Loaded, the left tip presses on the robot's own right thigh, whose normal turns with q (an
  // internal force: the robot's E16-E17 terms cancel; the ball test below has them).
  if (GetParam()) r.contacts[2].contact.s2 = test::surface(*scene_, "robot/r_thigh");
  EXPECT_LE(hessian_error(*scene_, r, options), 1e-6);
}

// Fingertips holding the ball of hand_ball_rotate.yaml, loaded: the ball's E16-E17 take each force
// at c - r z2, z2 turning with the ball.
TEST(PointContactHessianOnAnObject, MatchesCentralDifferences) {
  Scenario scenario = load_scenario(test::source_path("scenarios/hand_ball_rotate.yaml"));
  const PostureRequest r = test::with_point_tips(scenario);
  scenario.solver.hessian = HessianMode::Analytic;
  scenario.solver.w_torque = 1e-3;
  EXPECT_LE(hessian_error(scenario.scene, r, scenario.solver), 1e-6);
}

// E17's value: a fingertip pushing on the ball along one cone generator U_0 = (mu x2 + z2) /
// sqrt(1 + mu^2) only, with lambda = 10 N. Its force acts at c - r z2: against a tip of radius 0 at
// the same centre, the ball's moment changes by -(-r z2 x f) = r lambda mu / sqrt(1 + mu^2) y2.
TEST(PointContactEquilibrium, TheForceActsOneRadiusBelowTheCentre) {
  const double r = 0.008, lambda = 10.0;
  Scenario sharp = load_scenario(test::source_path("scenarios/hand_ball_rotate.yaml"));
  Scenario round = sharp;
  const PostureRequest request_sharp = test::with_point_tips(sharp, 0.0);
  const PostureRequest request_round = test::with_point_tips(round, r);
  PostureNlp nlp_sharp(sharp.scene, request_sharp, sharp.solver, {});
  PostureNlp nlp_round(round.scene, request_round, round.solver, {});
  ASSERT_EQ(nlp_sharp.n(), nlp_round.n());
  Eigen::VectorXd x(nlp_round.n());
  nlp_round.starting_point(x.data());
  const int nq = nlp_round.layout().nq;
  x.tail(x.size() - nq).setZero();
  x[nlp_round.layout().forces[0].first_column] = lambda;  // contact 0, generator 0
  Eigen::VectorXd g_sharp(nlp_sharp.m()), g_round(nlp_round.m());
  nlp_sharp.constraints(x.data(), true, g_sharp.data());
  nlp_round.constraints(x.data(), true, g_round.data());
  auto moment = [](PostureNlp& nlp, const Eigen::VectorXd& g) {
    for (size_t b = 0; b < nlp.blocks().size(); ++b)
      if (nlp.blocks()[b]->family() == "equilibrium")  // the ball's: the hand is fixed
        return Eigen::Vector3d(g.segment<3>(nlp.block_first_row(int(b)) + 3));
    return Eigen::Vector3d(Eigen::Vector3d::Constant(NAN));
  };
  const SurfaceRef s2 = request_round.contacts[0].contact.s2;
  const Entity& ball = round.scene.system.entity(s2.entity);
  ModelData data(ball);
  forward_kinematics(ball, x.segment(round.scene.system.offset(s2.entity), ball.nq()), data);
  const Surface& surface = round.scene.surfaces.get(s2);
  const Eigen::Vector3d y2 = data.T_WL[surface.link].linear() * surface.T_LS.linear().col(1);
  const double mu = round.solver.friction;
  const double scale = 1.0 / (ball.model->total_mass * round.scene.gravity.norm());
  const Eigen::Vector3d expected = scale * r * lambda * mu / std::sqrt(1.0 + mu * mu) * y2;
  EXPECT_GT(expected.norm(), 1e-4);
  EXPECT_TRUE((moment(nlp_round, g_round) - moment(nlp_sharp, g_sharp)).isApprox(expected, 1e-9))
      << (moment(nlp_round, g_round) - moment(nlp_sharp, g_sharp)).transpose() << " vs "
      << expected.transpose();
}

// A bilateral tip gripping the robot's own right thigh: free force components, the couple -r z2 x f
// turning with the thigh.
TEST_F(PointContactGeometry, BilateralTipHessianMatchesCentralDifferences) {
  SolverOptions options;
  options.hessian = HessianMode::Analytic;
  options.w_torque = 1e-3;
  PostureRequest r = request();
  r.contacts[2].loaded = r.contacts[3].loaded = true;
  r.contacts[2].contact.s2 = test::surface(*scene_, "robot/r_thigh");
  r.contacts[2].contact.bilateral = true;
  EXPECT_LE(hessian_error(*scene_, r, options), 1e-6);
}

// Starting forces (force_balance.h) for point tips holding the ball: they balance the ball with
// each force at its contact point c - r z2, recomputed here; taken at the centres instead, the
// same forces leave a moment (the couples).
TEST(PointContactStartingForces, BalanceTheBallWithTheForcesAtTheContactPoints) {
  Scenario scenario = load_scenario(test::source_path("scenarios/hand_ball_rotate.yaml"));
  const PostureRequest r = test::with_point_tips(scenario, 0.008);
  PostureNlp nlp(scenario.scene, r, scenario.solver, {});
  Eigen::VectorXd x(nlp.n());
  nlp.starting_point(x.data());
  NlpState& state = nlp.state();
  state.set_x(x.data());
  ASSERT_TRUE(balance_starting_forces(state, x).balanced);
  const System& system = scenario.scene.system;
  const int ball = system.find_entity("ball");
  const Entity& entity = system.entity(ball);
  ModelData data(entity);
  forward_kinematics(entity, x.segment(system.offset(ball), entity.nq()), data);
  const Eigen::Vector3d weight = entity.model->total_mass * scenario.scene.gravity;
  Eigen::Vector3d force = weight, at_contact = center_of_mass(entity, data).cross(weight);
  Eigen::Vector3d at_centre = at_contact;
  for (size_t t = 0; t < r.contacts.size(); ++t) {
    const ContactFrames& f = state.frames[t];
    ASSERT_EQ(r.contacts[t].contact.s2.entity, ball);
    force -= f.f[0];  // the ball carries s2: it receives -f
    at_contact -= (f.p[0] - 0.008 * f.z2).cross(f.f[0]);
    at_centre -= f.p[0].cross(f.f[0]);
  }
  const double scale = weight.norm();
  EXPECT_LE(force.norm() / scale, 1e-8);
  EXPECT_LE(at_contact.norm() / scale, 1e-8);
  EXPECT_GT(at_centre.norm() / scale, 1e-4);
}

INSTANTIATE_TEST_SUITE_P(PointContacts, PointContactHessian, ::testing::Bool(),
                         [](const auto& info) { return info.param ? "Loaded" : "Touched"; });

TEST_F(PointContactGeometry, AFingertipTouchesTheWallOneRadiusFromIt) {
  PostureRequest r = request();
  r.contacts.pop_back();  // the standing robot cannot also reach the floor
  const PostureSolver solver(*scene_, SolverOptions{});
  const PostureResult result = solver.solve(r);
  ASSERT_EQ(result.status, PostureStatus::Solved) << result.message;
  // The wall's face is the plane x = 0.6: the centre is one radius in front of it.
  EXPECT_NEAR(tip_centre(result.q, "robot/l_tip").x(), 0.6 - 0.02, 1e-6);
}

// Standing on both soles with the left fingertip loaded on the wall: the tip's force acts one
// radius in front of its centre, on the wall's plane, and the solution balances the robot (E16-E17)
// and its joints (E18) with the force there, recomputed here from the result alone.
TEST_F(PointContactGeometry, ALoadedFingertipLeansOnTheWall) {
  PostureRequest r = request();
  r.contacts.pop_back();
  const PostureSolver solver(*scene_, SolverOptions{});
  const PostureResult touched = solver.solve(r);  // case 1: the tip reaches the wall
  ASSERT_EQ(touched.status, PostureStatus::Solved) << touched.message;
  r.contacts[2].loaded = true;  // then leans on it from there
  r.contacts[2].placement_target.reset();
  r.q_init = touched.q;
  const PostureResult result = solver.solve(r);
  ASSERT_EQ(result.status, PostureStatus::Solved) << result.message;
  EXPECT_NEAR(tip_centre(result.q, "robot/l_tip").x(), 0.6 - 0.02, 1e-6);
  const Entity& robot = scene_->system.entity(0);
  ModelData data(robot);
  forward_kinematics(robot, result.q.head(robot.nq()), data);
  const Eigen::Vector3d weight = robot.model->total_mass * scene_->gravity;
  Eigen::Vector3d force = weight, moment = center_of_mass(robot, data).cross(weight);
  Eigen::VectorXd generalized = Eigen::VectorXd::Zero(robot.nq());
  Eigen::MatrixXd J(3, robot.nq());
  double tip_force = 0.0;
  for (const VertexForce& f : result.forces) {
    const Surface& s1 = scene_->surfaces.get(r.contacts[size_t(f.contact)].contact.s1);
    if (f.contact == 2) {
      EXPECT_NEAR(f.point_W.x(), 0.6, 1e-6);  // on the wall's face
      tip_force += f.force_W.norm();
    }
    force += f.force_W;
    moment += f.point_W.cross(f.force_W);
    point_jacobian_world(robot, data, s1.link, f.point_W, J);
    generalized += J.transpose() * f.force_W;
  }
  center_of_mass_jacobian(robot, data, J);
  generalized += J.transpose() * weight;
  EXPECT_GT(tip_force, 1.0);  // the tip really carries force
  const double scale = weight.norm();
  EXPECT_LE(force.norm() / scale, 1e-6);
  EXPECT_LE(moment.norm() / scale, 1e-6);
  const Eigen::VectorXd& tau = result.torques[0];
  EXPECT_LE((tau + generalized.tail(tau.size())).cwiseAbs().maxCoeff(), 1e-6);
}

// E18's value: the fingertip of hand_ball_rotate's first finger pushing along one cone generator
// U_0 = (mu x2 + z2) / sqrt(1 + mu^2) only, lambda = 10 N. Against a tip of radius 0 at the same
// centre, the couple -r z2 x f changes the torque of every revolute joint j above the tip by
//   -a_j . (-r z2 x f) = r lambda mu / sqrt(1 + mu^2) a_j . y2   (tau + J^T f = 0),
// computed here by hand from the joint axes; the other fingers' joints do not change.
TEST(PointContactTorques, TheCoupleTurnsEveryJointAboveTheTip) {
  const double r = 0.008, lambda = 10.0;
  Scenario sharp = load_scenario(test::source_path("scenarios/hand_ball_rotate.yaml"));
  Scenario round = sharp;
  const PostureRequest request_sharp = test::with_point_tips(sharp, 0.0);
  const PostureRequest request_round = test::with_point_tips(round, r);
  PostureNlp nlp_sharp(sharp.scene, request_sharp, sharp.solver, {});
  PostureNlp nlp_round(round.scene, request_round, round.solver, {});
  Eigen::VectorXd x(nlp_round.n());
  nlp_round.starting_point(x.data());
  const int nq = nlp_round.layout().nq;
  x.tail(x.size() - nq).setZero();
  x[nlp_round.layout().forces[0].first_column] = lambda;  // contact 0, generator 0
  const SurfaceRef s1 = request_round.contacts[0].contact.s1,
                   s2 = request_round.contacts[0].contact.s2;
  for (PostureNlp* nlp : {&nlp_sharp, &nlp_round}) {
    nlp->state().set_x(x.data());
    nlp->state().ensure_torques();
  }
  const Eigen::VectorXd delta =
      nlp_round.state().tau[size_t(s1.entity)] - nlp_sharp.state().tau[size_t(s1.entity)];
  const System& system = round.scene.system;
  const Entity& ball = system.entity(s2.entity);
  ModelData ball_data(ball);
  forward_kinematics(ball, x.segment(system.offset(s2.entity), ball.nq()), ball_data);
  const Surface& face = round.scene.surfaces.get(s2);
  const Eigen::Vector3d y2 = ball_data.T_WL[face.link].linear() * face.T_LS.linear().col(1);
  const Entity& hand = system.entity(s1.entity);
  ModelData data(hand);
  forward_kinematics(hand, x.segment(system.offset(s1.entity), hand.nq()), data);
  const Model& model = *hand.model;
  const double mu = round.solver.friction;
  Eigen::VectorXd expected = Eigen::VectorXd::Zero(model.num_dofs());
  for (int l = round.scene.surfaces.get(s1).link; l > 0; l = model.links[l].parent_link) {
    const Joint& joint = model.joints[model.links[l].parent_joint];
    if (joint.type == JointType::Revolute || joint.type == JointType::Continuous)
      expected[joint.dof] += joint.multiplier * r * lambda * mu / std::sqrt(1.0 + mu * mu) *
                             data.axis_W[model.links[l].parent_joint].dot(y2);
  }
  EXPECT_GT(expected.cwiseAbs().maxCoeff(), 1e-3);
  EXPECT_LE((delta - expected).cwiseAbs().maxCoeff(), 1e-12)
      << delta.transpose() << "\n vs\n " << expected.transpose();
}

TEST_F(PointContactGeometry, APointSurfaceIsOnlyS1) {
  PostureRequest r = request();
  std::swap(r.contacts[2].contact.s1, r.contacts[2].contact.s2);
  try {
    PostureSolver(*scene_, SolverOptions{}).validate_request(r);
    FAIL() << "a point surface as s2 was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "contact env/wall - robot/l_tip: a point surface can only be s1");
  }
}

}  // namespace
}  // namespace stanceplan
