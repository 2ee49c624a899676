// The dexterous-hand scenarios of docs/METHOD.md section 5 (scenario 2): the planner finds a plan
// for each within the scenario's node budget, the independent checker certifies it, and the plan
// does what the task says (the ball ends upside down, the pen is held by its front end), with at
// least three fingertips loaded at every step (search.min_contacts).
#include <gtest/gtest.h>

#include <cmath>

#include "planner/certify/certify.h"
#include "planner/io/plan_reader.h"
#include "planner/io/plan_writer.h"
#include "planner/search/stance_search.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"
#include "tests/support/scenario_motion.h"

namespace stanceplan {
namespace {

struct Planned {
  Scenario scenario;
  SearchResult result;
};

// The scenario's own options except the time limit: the node budget decides (deterministic), not
// how busy the machine is. CTest runs every test case in a process of its own, so each scenario is
// planned by one test case only.
Planned plan(const std::string& name) {
  Scenario scenario = load_scenario(test::source_path("scenarios/" + name + ".yaml"));
  SearchOptions options = scenario.search;
  options.time_limit_s = test::kTestTimeLimit;
  SearchResult result = StanceSearch(scenario, options).run();
  return {std::move(scenario), std::move(result)};
}

void expect_certified(const Planned& p, const std::string& name) {
  ASSERT_EQ(p.result.status, PlanStatus::Found) << p.result.message;
  EXPECT_LE(p.result.nodes_expanded, p.scenario.search.max_nodes);
  const std::string path = (test::temp_dir("hand") / (name + ".json")).string();
  write_plan(p.result.plan, p.scenario, path);
  const CertifyReport report = certify(read_plan(path));
  for (const CheckResult& c : report.checks)
    EXPECT_TRUE(c.passed()) << c.name << " " << c.worst << " at step " << c.step << ": "
                            << c.detail;
  EXPECT_TRUE(report.passed());
  EXPECT_GE(report.checks.size(), 12u);
}

// Loaded contacts of a step.
int loaded(const PlanStep& step) {
  int n = 0;
  for (const PlanContact& c : step.contacts) n += c.loaded;
  return n;
}

std::string face(const Scenario& s, const Contact& c) {
  return s.scene.surfaces.get(c.s2).name;
}

TEST(HandBallRotate, PlanCertifiedBallUpsideDownThreeFingertipsOrMoreAtEveryStep) {
  const Planned p = plan("hand_ball_rotate");
  expect_certified(p, "ball");
  ASSERT_EQ(p.result.status, PlanStatus::Found) << p.result.message;
  const auto& steps = p.result.plan.steps;
  ASSERT_GE(steps.size(), 9u);  // every fingertip moved at least once
  for (const PlanStep& step : steps) EXPECT_GE(loaded(step), 3) << "step " << &step - steps.data();
  // Southern faces (s0..s9) at the start, northern ones (n0..n9) at the end.
  for (const Contact& c : steps.front().stance.contacts()) EXPECT_EQ(face(p.scenario, c)[0], 's');
  for (const Contact& c : steps.back().stance.contacts()) EXPECT_EQ(face(p.scenario, c)[0], 'n');
  // The ball turned by a half turn about x, within 0.5 rad (the goal is the stance: the last
  // fingertip lands when all four are on northern faces, the ball a little short of the turn).
  const int ball = p.scenario.scene.system.find_entity("ball");
  const Eigen::Vector4d q =
      steps.back().q.segment<4>(p.scenario.scene.system.offset(ball) + Entity::kBaseQuaternion);
  const double angle_to_half_turn = 2.0 * std::acos(std::min(1.0, std::abs(q[1]) / q.norm()));
  EXPECT_LT(angle_to_half_turn, 0.5) << q.transpose();
  // The motion between the steps: every step moves (fingertips around the ball by the detour,
  // planner/motion/stance_rrt.h, where the straight path goes through it) and certifies sample by
  // sample.
  test::expect_motion_certified(p.scenario, p.result, "ball");
}

TEST(HandPenRegrasp, PlanCertifiedGraspMovesToTheFrontEnd) {
  const Planned p = plan("hand_pen_regrasp");
  expect_certified(p, "pen");
  ASSERT_EQ(p.result.status, PlanStatus::Found) << p.result.message;
  const auto& steps = p.result.plan.steps;
  for (const PlanStep& step : steps) EXPECT_GE(loaded(step), 3) << "step " << &step - steps.data();
  // Placement x is the position of a pad along the pen (the side faces' x axis is the pen's axis).
  auto along = [&](const PlanStep& step, const Contact& c) {
    return measure_placement(p.scenario.scene, c, step.q).x;
  };
  int behind_centre = 0;
  for (const Contact& c : steps.front().stance.contacts())
    behind_centre += along(steps.front(), c) < 0.0;
  EXPECT_EQ(behind_centre, 2);  // held by the middle: two pads on each side of the centre
  for (const Contact& c : steps.back().stance.contacts()) {
    EXPECT_GT(along(steps.back(), c), 0.02);  // every pad in the front half, clear of the centre
    EXPECT_LT(along(steps.back(), c), 0.08 - 0.004);  // and on the pen (16 cm long, 8 mm pads)
  }
  // The motion between the steps: every step moves and certifies sample by sample.
  test::expect_motion_certified(p.scenario, p.result, "pen");
}

}  // namespace
}  // namespace stanceplan
