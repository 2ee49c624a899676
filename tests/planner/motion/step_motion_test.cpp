// The motion between plan steps (planner/motion/, docs/METHOD.md section 7): interpolation,
// spacing, and a foot step that lifts along the normal, travels and lands, every sample holding
// the stance at its placement.
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>

#include "planner/model/kinematics.h"
#include "planner/motion/configuration_path.h"
#include "planner/motion/plan_motion.h"
#include "planner/motion/sample_spacing.h"
#include "tests/support/forward_step.h"

namespace stanceplan {
namespace {

// s1's origin above s2's plane (m), along s2's normal.
double height(const Scene& scene, const Contact& c, const Eigen::VectorXd& q) {
  const std::vector<ModelData> data = system_kinematics(scene.system, q);
  const Surface& s1 = scene.surfaces.get(c.s1);
  const Surface& s2 = scene.surfaces.get(c.s2);
  const Eigen::Isometry3d T1 = data[c.s1.entity].T_WL[s1.link] * s1.T_LS;
  const Eigen::Isometry3d T2 = data[c.s2.entity].T_WL[s2.link] * s2.T_LS;
  return (T1.translation() - T2.translation()).dot(T2.linear().col(2));
}

TEST(ConfigurationPath, JointsLinearlyAndRootsAlongTheShorterArc) {
  const Scene scene = test::humanoid_scene("flat_ground");
  Eigen::VectorXd a = test::standing_configuration(scene), b = a, q(a.size());
  b[7] = 0.4;
  b[0] = 1.0;
  const Eigen::Quaterniond turn(Eigen::AngleAxisd(1.0, Eigen::Vector3d::UnitZ()));
  b.segment<4>(3) << -turn.w(), -turn.x(), -turn.y(), -turn.z();  // the same turn, other sign
  interpolate_configuration(scene.system, a, b, 0.25, q);
  EXPECT_NEAR(q[7], 0.1, 1e-12);
  EXPECT_NEAR(q[0], 0.25, 1e-12);
  const Eigen::Quaterniond r(q[3], q[4], q[5], q[6]);
  EXPECT_NEAR(r.norm(), 1.0, 1e-12);
  EXPECT_NEAR(Eigen::AngleAxisd(r).angle(), 0.25, 1e-9);  // a quarter of the 1 rad turn
}

TEST(SampleSpacing, LargestJointStepAndLargestStepOfASurfaceVertex) {
  const Scene scene = test::humanoid_scene("flat_ground");
  SampleSpacing spacing(scene, {test::surface(scene, "robot/l_sole")});
  Eigen::VectorXd a = test::standing_configuration(scene), b = a;
  b[0] += 0.004;  // the root 4 mm forward
  const int knee = scene.system.entity(0).model->find_joint("l_knee_p");
  ASSERT_GE(knee, 0);
  b[7 + scene.system.entity(0).model->joints[knee].dof] += 0.03;
  const SpacingMeasure m = spacing.measure(a, b);
  EXPECT_NEAR(m.joint, 0.03, 1e-12);
  EXPECT_EQ(spacing.joint_name(m), "robot/l_knee_p");
  EXPECT_EQ(spacing.surface_name(m), "robot/l_sole");
  // The sole turns about the knee: more than the root's 4 mm, less than 4 mm + 0.03 rad x 0.5 m.
  EXPECT_GT(m.point, 0.004);
  EXPECT_LT(m.point, 0.004 + 0.03 * 0.5);
  EXPECT_NEAR(m.ratio(0.05, 0.01), std::max(0.6, m.point / 0.01), 1e-12);
}

TEST(StepMotion, FootLiftsAlongTheNormalTravelsAndLandsWithinTheSpacing) {
  test::ForwardStep fs = test::forward_step_plan();
  const Scene& scene = fs.scenario.scene;
  const MotionOptions options;
  const PlanMotionSummary summary = add_motion(scene, fs.scenario.solver, options, fs.plan);
  ASSERT_TRUE(summary.solved()) << summary.first_failure;
  ASSERT_EQ(summary.steps.size(), 2u);
  const auto& steps = fs.plan.steps;
  const Contact left = *steps[1].changed;
  std::vector<SurfaceRef> soles;
  for (const Contact& c : steps[0].stance.contacts()) soles.push_back(c.s1);
  SampleSpacing spacing(scene, soles);
  for (int i = 1; i <= 2; ++i) {
    const std::vector<MotionSample>& samples = steps[i].motion->samples;
    ASSERT_FALSE(samples.empty());
    Eigen::VectorXd previous = steps[i - 1].q;
    for (size_t k = 0; k <= samples.size(); ++k) {
      const Eigen::VectorXd& q = k < samples.size() ? samples[k].q : steps[i].q;
      EXPECT_LE(spacing.measure(previous, q).ratio(options.joint_spacing, options.point_spacing),
                1.0 + 1e-9)
          << "step " << i << ", sample " << k;
      previous = q;
      if (k == samples.size()) break;
      // Every contact of the stance stays where step i-1 has it, and carries force.
      for (const Contact& c : steps[i - 1].stance.contacts()) {
        const Placement p = measure_placement(scene, c, q),
                        p0 = measure_placement(scene, c, steps[i - 1].q);
        EXPECT_NEAR(p.x, p0.x, 1e-5);
        EXPECT_NEAR(p.y, p0.y, 1e-5);
        EXPECT_NEAR(p.theta, p0.theta, 1e-5);
      }
      EXPECT_EQ(samples[k].forces.size(), 4u * steps[i - 1].stance.contacts().size());
    }
  }
  // The left sole rises straight up to the clearance (lift), and comes straight down onto its
  // new placement (approach): its first and last samples are above its two placements.
  const std::vector<MotionSample>& swing = steps[2].motion->samples;
  double top = 0.0;
  for (const MotionSample& s : swing) top = std::max(top, height(scene, left, s.q));
  EXPECT_GE(top, options.clearance - 1e-6);
  const Placement start = measure_placement(scene, left, steps[1].q);
  const Placement end = measure_placement(scene, left, steps[2].q);
  EXPECT_NEAR(end.x - start.x, 0.2, 1e-4);
  for (const MotionSample* s : {&swing.front(), &swing.back()}) {
    const Placement p = measure_placement(scene, left, s->q);
    const Placement& under = s == &swing.front() ? start : end;
    EXPECT_NEAR(p.x, under.x, 1e-5);
    EXPECT_NEAR(p.y, under.y, 1e-5);
    const double h = height(scene, left, s->q);
    EXPECT_GT(h, 0.0);
    EXPECT_LE(h, options.point_spacing + 1e-6);
  }
  EXPECT_GT(summary.steps[1].solves, int(swing.size()) - 1);
}

TEST(StepMotion, StepsThatDoNotHoldTheStanceAtOnePlacementAreRefused) {
  test::ForwardStep fs = test::forward_step_plan();
  const Scene& scene = fs.scenario.scene;
  StepMotionPlanner planner(scene, fs.scenario.solver, MotionOptions{});
  PlanStep moved = fs.plan.steps[1];
  moved.q[0] += 0.05;  // the whole robot 5 cm forward: the right sole slides
  const StepMotionResult r = planner.plan(fs.plan.steps[1], moved);
  EXPECT_EQ(r.motion.status, MotionStatus::EndsDisagree);
  EXPECT_EQ(r.motion.message,
            "robot/r_sole-env/floor is not at the same placement in both steps (moved 0.05 m, "
            "turned 0 rad)");
  EXPECT_EQ(r.solves, 0);
}

TEST(StepMotion, BadOptionsAreRefusedByName) {
  MotionOptions o;
  o.clearance = -0.01;
  EXPECT_EQ(check_motion_options(o), "clearance: expected a number >= 0 (m), found -0.01");
}

}  // namespace
}  // namespace stanceplan
