// The IK-statics solver on the humanoid: physical residuals of solved postures (docs/METHOD.md
// section 4), the three uses (realise, case 1, case 2), infeasibility as a status, determinism
// and thread safety.
#include <gtest/gtest.h>

#include <cstring>
#include <thread>

#include "planner/collision/signed_distance.h"
#include "planner/model/kinematics.h"
#include "planner/solver/ipopt_adapter.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

using test::task;

SolverOptions default_options() {
  SolverOptions options;
  options.print_level = std::getenv("IPOPT_PRINT") ? 5 : 0;
  return options;
}

double robot_mass(const Scene& scene) {
  return scene.system.entity(0).model->total_mass;
}

Eigen::Vector3d robot_com(const Scene& scene, const Eigen::VectorXd& q) {
  const Entity& robot = scene.system.entity(0);
  ModelData data(robot);
  forward_kinematics(robot, q.head(robot.nq()), data);
  return center_of_mass(robot, data);
}

// True when p (x, y) is inside the convex hull of the points (x, y), by the winding of the hull.
bool inside_convex_hull(const std::vector<Eigen::Vector2d>& points, const Eigen::Vector2d& p) {
  std::vector<Eigen::Vector2d> pts = points;
  std::sort(pts.begin(), pts.end(),
            [](auto& a, auto& b) { return a.x() < b.x() || (a.x() == b.x() && a.y() < b.y()); });
  auto cross = [](const Eigen::Vector2d& o, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
    return (a - o).x() * (b - o).y() - (a - o).y() * (b - o).x();
  };
  std::vector<Eigen::Vector2d> hull(2 * pts.size());
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && cross(hull[k - 2], hull[k - 1], pts[i - 1]) <= 0) --k;
    hull[k++] = pts[i - 1];
  }
  hull.resize(k - 1);
  for (size_t i = 0; i < hull.size(); ++i)
    if (cross(hull[i], hull[(i + 1) % hull.size()], p) < 0) return false;
  return true;
}

// The physics a checker verifies (docs/PLAN_FORMAT.md), from the result alone.
void expect_physically_valid(const Scene& scene, const PostureRequest& request,
                             const PostureResult& r, double friction) {
  const double mass = robot_mass(scene), weight = mass * 9.81;
  Eigen::Vector3d force = Eigen::Vector3d(0, 0, -weight);
  Eigen::Vector3d moment = robot_com(scene, r.q).cross(Eigen::Vector3d(0, 0, -weight));
  for (const VertexForce& f : r.forces) {
    force += f.force_W;
    moment += f.point_W.cross(f.force_W);
    // Unilateral frictional contact on a horizontal or vertical surface: normal of s2.
    const Contact& c = request.contacts[f.contact].contact;
    const Surface& s2 = scene.surfaces.get(c.s2);
    const Eigen::Vector3d n = s2.normal_L();  // environment links are not rotated
    const double fn = f.force_W.dot(n);
    EXPECT_GE(fn, -1e-6);
    EXPECT_LE((f.force_W - fn * n).norm(), friction * fn + 1e-6);
  }
  EXPECT_LE(force.norm(), 1e-6 * weight);
  EXPECT_LE(moment.norm(), 1e-6 * weight);
  const Model& model = *scene.system.entity(0).model;
  for (int k = 0; k < model.num_dofs(); ++k) {
    const Joint& joint = model.joints[model.dof_joints[k]];
    EXPECT_GE(r.q[7 + k], joint.lower - 1e-9) << joint.name;
    EXPECT_LE(r.q[7 + k], joint.upper + 1e-9) << joint.name;
    EXPECT_LE(std::abs(r.torques[0][k]), joint.effort * (1 + 1e-6)) << joint.name;
  }
  EXPECT_NEAR(r.q.segment<4>(3).norm(), 1.0, 1e-12);
}

class HumanoidFlat : public ::testing::Test {
 protected:
  static void SetUpTestSuite() { scene_ = new Scene(test::humanoid_scene("wall")); }
  static void TearDownTestSuite() { delete scene_; }
  static Scene* scene_;

  PostureRequest standing_request() const {
    PostureRequest request;
    request.contacts = {task(*scene_, "robot/l_sole", "env/floor"),
                        task(*scene_, "robot/r_sole", "env/floor")};
    request.q_init = test::standing_configuration(*scene_);
    return request;
  }
};
Scene* HumanoidFlat::scene_ = nullptr;

TEST_F(HumanoidFlat, StandingOnBothFeetBalancesTheWeight) {
  const PostureRequest request = standing_request();
  const PostureResult result = PostureSolver(*scene_, default_options()).solve(request);
  ASSERT_EQ(result.status, PostureStatus::Solved) << result.message;
  Eigen::Vector3d total = Eigen::Vector3d::Zero();
  std::vector<Eigen::Vector2d> support;
  for (const VertexForce& f : result.forces) {
    total += f.force_W;
    support.push_back(f.point_W.head<2>());
  }
  const double weight = robot_mass(*scene_) * 9.81;
  EXPECT_NEAR(total.z() / weight, 1.0, 1e-6);
  EXPECT_NEAR(total.head<2>().norm() / weight, 0.0, 1e-6);
  EXPECT_EQ(result.forces.size(), 8u);
  EXPECT_TRUE(inside_convex_hull(support, robot_com(*scene_, result.q).head<2>()));
  expect_physically_valid(*scene_, request, result, 1.0);
  for (const auto& [family, residual] : result.residuals) EXPECT_LE(residual, 1e-6) << family;
}

// Case 2: both soles touch, only the right one carries force: the CoM moves above it.
TEST_F(HumanoidFlat, Case2LiftingTheLeftFootPutsTheComAboveTheRightSole) {
  const PostureSolver solver(*scene_, default_options());
  const PostureResult standing = solver.solve(standing_request());
  ASSERT_EQ(standing.status, PostureStatus::Solved);
  PostureRequest request = standing_request();
  for (int i = 0; i < 2; ++i) request.contacts[i].placement = standing.placements[i];
  request.contacts[0].loaded = false;  // the left sole is about to leave
  request.q_init = standing.q;
  const PostureResult result = solver.solve(request);
  ASSERT_EQ(result.status, PostureStatus::Solved) << result.message;
  std::vector<Eigen::Vector2d> right_sole;
  for (const VertexForce& f : result.forces) {
    EXPECT_EQ(f.contact, 1);
    right_sole.push_back(f.point_W.head<2>());
  }
  EXPECT_EQ(right_sole.size(), 4u);
  EXPECT_TRUE(inside_convex_hull(right_sole, robot_com(*scene_, result.q).head<2>()));
  // Both soles still exactly where they were (fixed placements, E10-E13).
  for (int i = 0; i < 2; ++i) {
    EXPECT_NEAR(result.placements[i].x, standing.placements[i].x, 1e-6);
    EXPECT_NEAR(result.placements[i].y, standing.placements[i].y, 1e-6);
    EXPECT_NEAR(result.placements[i].theta, standing.placements[i].theta, 1e-6);
  }
  expect_physically_valid(*scene_, request, result, 1.0);
}

// Case 1: the right palm is added on the wall: placement chosen by the solver inside the wall's
// polygon, touched but unloaded.
TEST_F(HumanoidFlat, Case1AddingTheRightHandOnTheWall) {
  const PostureSolver solver(*scene_, default_options());
  const PostureResult standing = solver.solve(standing_request());
  ASSERT_EQ(standing.status, PostureStatus::Solved);
  PostureRequest request = standing_request();
  for (int i = 0; i < 2; ++i) request.contacts[i].placement = standing.placements[i];
  request.contacts.push_back(task(*scene_, "robot/r_palm", "env/wall", false));
  // A local solver needs a guess in the right basin (the search gives it the milestone): the
  // arm raised forward, the wrist bent so that the palm faces the wall.
  request.q_init = standing.q;
  const Model& model = *scene_->system.entity(0).model;
  request.q_init[7 + model.find_dof("r_shoulder_p")] = -1.4;
  request.q_init[7 + model.find_dof("r_wrist_p")] = -1.2;
  const PostureResult result = solver.solve(request);
  ASSERT_EQ(result.status, PostureStatus::Solved)
      << result.message << " iterations " << result.iterations;
  for (const VertexForce& f : result.forces) EXPECT_NE(f.contact, 2);  // the hand is unloaded
  // Every palm vertex on the wall plane and inside its polygon.
  const Surface& palm = scene_->surfaces.get(request.contacts[2].contact.s1);
  const Surface& wall = scene_->surfaces.get(request.contacts[2].contact.s2);
  const Entity& robot = scene_->system.entity(0);
  ModelData data(robot);
  forward_kinematics(robot, result.q.head(robot.nq()), data);
  const Entity& env = scene_->system.entity(1);
  ModelData env_data(env);
  forward_kinematics(env, Eigen::VectorXd(), env_data);
  const Eigen::Isometry3d T_WS2 = env_data.T_WL[wall.link] * wall.T_LS;
  Eigen::Vector2d lo = wall.vertices_S[0], hi = wall.vertices_S[0];
  for (const auto& v : wall.vertices_S) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  for (const Eigen::Vector3d& v_L : palm.vertices_L()) {
    const Eigen::Vector3d p_S2 = T_WS2.inverse() * (data.T_WL[palm.link] * v_L);
    EXPECT_NEAR(p_S2.z(), 0.0, 1e-6);
    EXPECT_GE(p_S2.x(), lo.x() - 1e-6);
    EXPECT_LE(p_S2.x(), hi.x() + 1e-6);
    EXPECT_GE(p_S2.y(), lo.y() - 1e-6);
    EXPECT_LE(p_S2.y(), hi.y() + 1e-6);
  }
  expect_physically_valid(*scene_, request, result, 1.0);
}

TEST_F(HumanoidFlat, AContactOutOfReachIsInfeasibleNotAnException) {
  const PostureSolver solver(*scene_, default_options());
  const PostureResult standing = solver.solve(standing_request());
  ASSERT_EQ(standing.status, PostureStatus::Solved);
  PostureRequest request = standing_request();
  for (int i = 0; i < 2; ++i) request.contacts[i].placement = standing.placements[i];
  // The feet are fixed 0.6 m from the wall; the palm's placement is fixed 2.5 m up the wall.
  ContactTask hand = task(*scene_, "robot/l_palm", "env/wall", false);
  hand.placement = Placement{0.0, 2.5, 0.0};
  request.contacts.push_back(hand);
  request.q_init = standing.q;
  const PostureResult result = solver.solve(request);
  EXPECT_NE(result.status, PostureStatus::Solved);
  EXPECT_LE(result.iterations,
            default_options().max_iterations * default_options().max_active_set_rounds);
  EXPECT_GT(result.residuals.at("contact_geometry"), 1e-3);
}

// A crouch (knees held bent by their lower limit) needs real knee torque: the knee lies forward
// of the line of the ground force. Feasible with the URDF's limits, not with 5 % of them.
TEST_F(HumanoidFlat, WeakJointsMakeACrouchInfeasibleBecauseOfTorqueLimits) {
  auto crouching = [](double effort_scale) {
    Scene scene = test::humanoid_scene("wall");
    auto model = std::make_shared<Model>(*scene.system.entity(0).model);
    for (Joint& joint : model->joints) {
      joint.effort *= effort_scale;
      if (joint.name == "l_knee_p" || joint.name == "r_knee_p") joint.lower = 1.2;
    }
    const_cast<Entity&>(scene.system.entity(0)).model = model;
    return scene;
  };
  for (double scale : {1.0, 0.05}) {
    const Scene scene = crouching(scale);
    PostureRequest request;
    request.contacts = {task(scene, "robot/l_sole", "env/floor"),
                        task(scene, "robot/r_sole", "env/floor")};
    request.q_init = test::standing_configuration(scene);
    const Model& model = *scene.system.entity(0).model;
    request.q_init[2] = 0.8;
    for (const char* side : {"l_", "r_"}) {
      request.q_init[7 + model.find_dof(std::string(side) + "hip_p")] = -0.6;
      request.q_init[7 + model.find_dof(std::string(side) + "knee_p")] = 1.2;
      request.q_init[7 + model.find_dof(std::string(side) + "ankle_p")] = -0.6;
    }
    SolverOptions options = default_options();
    options.diagnose_infeasibility = true;
    const PostureResult result = PostureSolver(scene, options).solve(request);
    if (scale == 1.0) {
      ASSERT_EQ(result.status, PostureStatus::Solved) << result.message;
      continue;
    }
    EXPECT_NE(result.status, PostureStatus::Solved);
    EXPECT_EQ(result.blocking_family, "torque_limits") << result.message;
    EXPECT_NE(result.message.find("infeasible because of torque_limits (solved without them)"),
              std::string::npos)
        << result.message;
  }
}

// E19 rows far from their limits at the start are left out (SolverOptions::torque_active_fraction)
// and added when a solution exceeds them. With the efforts cut to 12 % the crouch's knee limit
// binds: whatever the fraction (every row, half, or nearly none at the start), the solution keeps
// every joint within its limit, reports the worst ratio over all joints, and has a joint at it.
TEST_F(HumanoidFlat, TorqueRowsLeftOutAtTheStartStillHoldAtTheSolution) {
  Scene scene = test::humanoid_scene("wall");
  auto model = std::make_shared<Model>(*scene.system.entity(0).model);
  for (Joint& joint : model->joints) {
    joint.effort *= 0.12;
    if (joint.name == "l_knee_p" || joint.name == "r_knee_p") joint.lower = 1.2;
  }
  const_cast<Entity&>(scene.system.entity(0)).model = model;
  PostureRequest request;
  request.contacts = {task(scene, "robot/l_sole", "env/floor"),
                      task(scene, "robot/r_sole", "env/floor")};
  request.q_init = test::standing_configuration(scene);
  request.q_init[2] = 0.8;
  for (const char* side : {"l_", "r_"}) {
    request.q_init[7 + model->find_dof(std::string(side) + "hip_p")] = -0.6;
    request.q_init[7 + model->find_dof(std::string(side) + "knee_p")] = 1.2;
    request.q_init[7 + model->find_dof(std::string(side) + "ankle_p")] = -0.6;
  }
  for (double fraction : {0.0, 0.5, 0.999}) {
    SolverOptions options = default_options();
    options.torque_active_fraction = fraction;
    const PostureResult r = PostureSolver(scene, options).solve(request);
    ASSERT_EQ(r.status, PostureStatus::Solved) << "fraction " << fraction << ": " << r.message;
    double worst = 0.0;
    for (int k = 0; k < model->num_dofs(); ++k) {
      const Joint& joint = model->joints[model->dof_joints[k]];
      EXPECT_LE(std::abs(r.torques[0][k]), joint.effort * (1 + 1e-6))
          << joint.name << ", fraction " << fraction;
      worst = std::max(worst, std::abs(r.torques[0][k]) / joint.effort);
    }
    EXPECT_GT(worst, 0.999) << "fraction " << fraction << ": a limit binds";
    EXPECT_LE(r.residuals.at("torque_limits"), 1e-6) << "fraction " << fraction;
  }
}

// Polygon rows (a sole vertex inside an edge of the floor, case 1's E10-E11 relaxation) of
// vertices far from their edges at the start are left out (SolverOptions::polygon_active_distance)
// and added when a solution crosses them. On a 0.7 m slab, the milestone 0.4 m ahead pulls the
// standing robot (soles 0.2 m from the front edge: no row enters) over the edge: the first round's
// solution leaves the slab, the second holds the soles on its edge, where every row kept gives
// the same posture.
TEST(PolygonActiveSet, RowsLeftOutAtTheStartStillHoldAtTheSolution) {
  SceneSpec spec;
  EntitySpec ledge;
  ledge.name = "env";
  ledge.kind = EntityKind::Environment;
  ledge.urdf = test::source_path("tests/data/ledge/ledge.urdf");
  ledge.surfaces = test::source_path("tests/data/ledge/ledge.surfaces.yaml");
  spec.entities = {test::humanoid_spec(), ledge};
  const Scene scene = build_scene(spec);
  PostureRequest request;
  request.contacts = {task(scene, "robot/l_sole", "env/floor"),
                      task(scene, "robot/r_sole", "env/floor")};
  request.q_init = test::standing_configuration(scene);
  request.q_ref = request.q_init;
  request.q_ref[0] += 0.4;
  SolverOptions every_row = default_options();
  every_row.polygon_active_distance = INFINITY;
  const PostureResult reference = PostureSolver(scene, every_row).solve(request);
  const PostureResult result = PostureSolver(scene, default_options()).solve(request);
  for (const PostureResult* r : {&reference, &result}) {
    ASSERT_EQ(r->status, PostureStatus::Solved) << r->message;
    double front = -INFINITY;
    for (const VertexForce& f : r->forces) front = std::max(front, f.point_W.x());
    EXPECT_NEAR(front, 0.35, 1e-6);  // on the slab's front edge
    EXPECT_LE(r->residuals.at("polygon"), 1e-6);
    expect_physically_valid(scene, request, *r, 1.0);
  }
  EXPECT_LE((result.q - reference.q).lpNorm<Eigen::Infinity>(), 1e-3);
  // One round is not enough: the edge's rows were left out at the start.
  SolverOptions one_round = default_options();
  one_round.max_active_set_rounds = 1;
  const PostureResult first = PostureSolver(scene, one_round).solve(request);
  EXPECT_EQ(first.status, PostureStatus::Infeasible);
  EXPECT_EQ(first.message.rfind("polygon: vertices still outside their polygon after 1 active-set "
                                "rounds",
                                0),
            0u)
      << first.message;
  EXPECT_GT(first.residuals.at("polygon"), 0.01);
}

// The smallest signed distance over the candidate pairs that a request does not exclude.
double closest_pair(const Scene& scene, const PostureSolver& solver, const PostureRequest& request,
                    const Eigen::VectorXd& q, int* checked) {
  const std::vector<bool> excluded = solver.excluded_pairs(request);
  std::vector<ModelData> data;
  for (int e = 0; e < scene.system.num_entities(); ++e) {
    const Entity& entity = scene.system.entity(e);
    data.emplace_back(entity);
    forward_kinematics(entity, q.segment(scene.system.offset(e), entity.nq()), data.back());
  }
  CollisionData work(scene.system, *scene.collision);
  work.update(*scene.collision, data);
  double closest = INFINITY;
  *checked = 0;
  for (size_t p = 0; p < excluded.size(); ++p) {
    if (excluded[p]) continue;
    ++*checked;
    closest = std::min(closest, signed_distance(*scene.collision, work, int(p)).distance);
  }
  return closest;
}

// The feet touch the floor through their contacts while the milestone pulls the left hand into
// the chest (4 cm deep). Without E20 the solution follows it into the chest; with E20 no pair
// other than the two touching ones comes closer than the margin.
TEST_F(HumanoidFlat, TouchingThroughOneContactPenetratesThroughNoOtherPair) {
  const Scene& scene = *scene_;
  PostureRequest request = standing_request();
  const Model& model = *scene.system.entity(0).model;
  request.q_init[7 + model.find_dof("l_shoulder_p")] = -0.8;
  request.q_init[7 + model.find_dof("l_shoulder_y")] = -1.2;
  request.q_init[7 + model.find_dof("l_elbow_p")] = -2.2;
  request.q_ref = request.q_init;
  SolverOptions options = default_options();
  int checked = 0;
  options.enforce_collisions = false;
  const PostureSolver free_solver(scene, options);
  const PostureResult free = free_solver.solve(request);
  ASSERT_EQ(free.status, PostureStatus::Solved) << free.message;
  EXPECT_LT(closest_pair(scene, free_solver, request, free.q, &checked), -0.01);
  options.enforce_collisions = true;
  const PostureSolver solver(scene, options);
  const PostureResult result = solver.solve(request);
  ASSERT_EQ(result.status, PostureStatus::Solved) << result.message;
  expect_physically_valid(scene, request, result, 1.0);
  EXPECT_GE(closest_pair(scene, solver, request, result.q, &checked),
            options.collision_margin - 1e-4);
  EXPECT_EQ(checked, static_cast<int>(scene.collision->pairs().size()) - 2);
}

// On the left sole, the right foot 4-5 cm up and the reference putting it back on the floor (the
// standing posture): E20 keeps it at the margin; with the contact approaching (a motion's link
// coming down off the normal, PostureRequest::approaching) that one pair may come below the
// margin, down to touching and never into the floor, while every other pair keeps the margin.
TEST_F(HumanoidFlat, AnApproachingContactMayComeBelowTheMarginOnlyForItsOwnPair) {
  const Scene& scene = *scene_;
  SolverOptions options = default_options();
  options.w_configuration *= 300.0;  // the reference dominates, as in a motion's projection
  options.max_iterations = 300;
  const PostureSolver solver(scene, options);
  const PostureResult standing = solver.solve(standing_request());
  ASSERT_EQ(standing.status, PostureStatus::Solved) << standing.message;
  const Model& model = *scene.system.entity(0).model;
  PostureRequest request = standing_request();
  request.contacts.pop_back();
  request.q_init = standing.q;
  request.q_init[7 + model.find_dof("r_hip_p")] -= 0.3;
  request.q_init[7 + model.find_dof("r_knee_p")] += 0.6;
  request.q_init[7 + model.find_dof("r_ankle_p")] -= 0.3;
  request.q_ref = standing.q;
  const SurfaceRef sole = test::surface(scene, "robot/r_sole");
  const SurfaceRef floor = test::surface(scene, "env/floor");
  const int pair = scene.collision->find_pair(sole.entity, scene.surfaces.get(sole).link,
                                              floor.entity, scene.surfaces.get(floor).link);
  ASSERT_GE(pair, 0);
  const auto foot_to_floor = [&](const Eigen::VectorXd& q) {
    CollisionData work(scene.system, *scene.collision);
    work.update(*scene.collision, system_kinematics(scene.system, q));
    return signed_distance(*scene.collision, work, pair).distance;
  };
  ASSERT_GT(foot_to_floor(request.q_init), 0.03);
  // With the margin the foot stops above it (this solve even stalls there, at the bound).
  const PostureResult kept = solver.solve(request);
  if (kept.status == PostureStatus::Solved) {
    EXPECT_GE(foot_to_floor(kept.q), options.collision_margin - 1e-4);
  }
  request.approaching = {standing_request().contacts[1].contact};
  const PostureResult down = solver.solve(request);
  ASSERT_EQ(down.status, PostureStatus::Solved) << down.message;
  EXPECT_LT(foot_to_floor(down.q), 0.5 * options.collision_margin);
  EXPECT_GE(foot_to_floor(down.q), -1e-4);
  request.approaching.clear();  // every other pair at the margin: all of them but the foot's
  request.contacts.push_back(standing_request().contacts[1]);
  int checked = 0;
  EXPECT_GE(closest_pair(scene, solver, request, down.q, &checked),
            options.collision_margin - 1e-4);
}

TEST_F(HumanoidFlat, CallingTwiceGivesBitwiseEqualResults) {
  const PostureSolver solver(*scene_, default_options());
  const PostureResult a = solver.solve(standing_request());
  const PostureResult b = solver.solve(standing_request());
  ASSERT_EQ(a.q.size(), b.q.size());
  EXPECT_EQ(0, std::memcmp(a.q.data(), b.q.data(), sizeof(double) * a.q.size()));
  ASSERT_EQ(a.forces.size(), b.forces.size());
  for (size_t i = 0; i < a.forces.size(); ++i) EXPECT_EQ(a.forces[i].force_W, b.forces[i].force_W);
  EXPECT_EQ(a.iterations, b.iterations);
}

TEST_F(HumanoidFlat, TwoThreadsGiveTheSameResultsAsOne) {
  const PostureSolver solver(*scene_, default_options());
  // 50 requests: the standing posture from 50 different initial guesses.
  std::vector<PostureRequest> requests;
  for (int i = 0; i < 50; ++i) {
    PostureRequest r = standing_request();
    r.q_init[0] = 0.002 * i;
    r.q_init[7 + scene_->system.entity(0).model->find_dof("chest_y")] = 0.01 * (i % 7);
    requests.push_back(r);
  }
  std::vector<PostureResult> serial(50), parallel(50);
  for (int i = 0; i < 50; ++i) serial[i] = solver.solve(requests[i]);
  std::thread t1([&] {
    for (int i = 0; i < 50; i += 2) parallel[i] = solver.solve(requests[i]);
  });
  std::thread t2([&] {
    for (int i = 1; i < 50; i += 2) parallel[i] = solver.solve(requests[i]);
  });
  t1.join();
  t2.join();
  for (int i = 0; i < 50; ++i) {
    EXPECT_EQ(serial[i].status, parallel[i].status) << i;
    ASSERT_EQ(serial[i].q.size(), parallel[i].q.size());
    EXPECT_EQ(0, std::memcmp(serial[i].q.data(), parallel[i].q.data(),
                             sizeof(double) * serial[i].q.size()))
        << i;
  }
}

TEST_F(HumanoidFlat, IpoptDerivativeCheckerFindsNoError) {
  SolverOptions options = default_options();
  options.derivative_test = true;
  options.max_iterations = 1;
  PostureRequest request = standing_request();
  request.q_init[7 + scene_->system.entity(0).model->find_dof("l_knee_p")] = 0.3;
  PostureNlp nlp(*scene_, request, options, {});
  const IpoptRun run = run_ipopt(nlp, options);
  EXPECT_NE(run.derivative_report.find("No errors detected by derivative checker"),
            std::string::npos)
      << run.derivative_report.substr(0, 3000);
}

TEST_F(HumanoidFlat, MalformedRequestsThrowWithAPreciseMessage) {
  const PostureSolver solver(*scene_, default_options());
  PostureRequest request = standing_request();
  request.q_init.resize(5);
  EXPECT_THROW(solver.solve(request), std::invalid_argument);
  request = standing_request();
  request.contacts.push_back(task(*scene_, "robot/l_sole", "env/wall"));
  try {
    solver.solve(request);
    FAIL();
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(
        e.what(),
        "surface robot/l_sole is in two contacts (a contact's smaller surface s1 is in no other)");
  }
}

}  // namespace
}  // namespace stanceplan
