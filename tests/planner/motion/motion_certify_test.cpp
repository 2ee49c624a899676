// `certify` on motions (docs/PLAN_FORMAT.md, "What a checker verifies"): a computed motion
// certifies sample by sample and survives the file (format @2); one sample moved, by a joint jump,
// into the floor or off balance, fails the check that names it.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "planner/certify/certify.h"
#include "planner/io/plan_reader.h"
#include "planner/io/plan_writer.h"
#include "planner/motion/plan_motion.h"
#include "planner/util/text_file.h"
#include "tests/support/forward_step.h"

namespace stanceplan {
namespace {

class CertifiedMotion : public ::testing::Test {
 protected:
  void SetUp() override {
    summary_ = add_motion(fs_.scenario.scene, fs_.scenario.solver, MotionOptions{}, fs_.plan);
    ASSERT_TRUE(summary_.solved()) << summary_.first_failure;
  }
  CertifyReport certify_plan() const {
    return certify(fs_.scenario.scene, fs_.scenario.solver.friction, fs_.plan);
  }
  const CheckResult& check(const CertifyReport& report, const std::string& name) const {
    for (const CheckResult& c : report.checks)
      if (c.name == name) return c;
    ADD_FAILURE() << "no check " << name;
    return report.checks.front();
  }
  // The middle sample of the swing (step 1 -> 2): the left foot is in the air.
  MotionSample& swing_sample() {
    auto& samples = fs_.plan.steps[2].motion->samples;
    return samples[samples.size() / 2];
  }
  int swing_index() const { return int(fs_.plan.steps[2].motion->samples.size() / 2); }
  void expect_fails_at_swing_sample(const std::string& name) {
    const CertifyReport report = certify_plan();
    const CheckResult& c = check(report, name);
    EXPECT_FALSE(c.passed()) << name;
    EXPECT_EQ(c.step, 2);
    EXPECT_EQ(c.detail.rfind("motion sample " + std::to_string(swing_index()) + ": ", 0), 0u)
        << c.detail;
    EXPECT_EQ(report.first_failed_step, 2);
  }

  test::ForwardStep fs_ = test::forward_step_plan();
  PlanMotionSummary summary_;
};

TEST_F(CertifiedMotion, EverySampleCertifiesInMemoryAndThroughItsFile) {
  const CertifyReport report = certify_plan();
  for (const CheckResult& c : report.checks)
    EXPECT_TRUE(c.passed()) << c.name << " " << c.worst << " at step " << c.step << ": "
                            << c.detail;
  for (const char* name : {"motion status", "motion joint step", "motion point step"})
    EXPECT_TRUE(check(report, name).passed());
  const std::string path = (test::temp_dir("motion") / "forward_step.json").string();
  write_plan(fs_.plan, fs_.scenario, path);
  const nlohmann::json file = nlohmann::json::parse(read_text_file(path));
  EXPECT_EQ(file["format"], "stanceplan/plan@2");
  EXPECT_FALSE(file["steps"][0].contains("motion"));
  EXPECT_EQ(file["steps"][2]["motion"]["status"], "solved");
  const LoadedPlan loaded = read_plan(path);
  ASSERT_TRUE(loaded.plan.steps[2].motion.has_value());
  const auto& read = loaded.plan.steps[2].motion->samples;
  ASSERT_EQ(read.size(), fs_.plan.steps[2].motion->samples.size());
  EXPECT_EQ(read[3].q, fs_.plan.steps[2].motion->samples[3].q);  // full precision
  const CertifyReport from_file = certify(loaded);
  EXPECT_TRUE(from_file.passed());
  EXPECT_EQ(from_file.checks.size(), report.checks.size());
}

TEST_F(CertifiedMotion, AJointJumpFailsTheJointSpacing) {
  const int knee = fs_.scenario.scene.system.entity(0).model->find_joint("l_knee_p");
  swing_sample().q[7 + fs_.scenario.scene.system.entity(0).model->joints[knee].dof] += 0.2;
  const CertifyReport report = certify_plan();
  const CheckResult& c = check(report, "motion joint step");
  EXPECT_FALSE(c.passed());
  EXPECT_GE(c.worst, 0.15);
  EXPECT_EQ(c.step, 2);
  const std::string k = std::to_string(swing_index());
  const std::string before = "motion sample " + std::to_string(swing_index() - 1) + " to ";
  EXPECT_TRUE(c.detail == before + "motion sample " + k + ": robot/l_knee_p" ||
              c.detail == "motion sample " + k + " to motion sample " +
                              std::to_string(swing_index() + 1) + ": robot/l_knee_p")
      << c.detail;
  EXPECT_EQ(report.first_failed_step, 2);
}

TEST_F(CertifiedMotion, APenetrationFailsInterpenetration) {
  swing_sample().q[2] -= 0.08;  // the whole robot 8 cm down: the swinging foot into the floor
  expect_fails_at_swing_sample("interpenetration");
}

TEST_F(CertifiedMotion, LostEquilibriumFailsTheForceBalance) {
  for (VertexForce& f : swing_sample().forces) f.force_W *= 0.9;
  expect_fails_at_swing_sample("equilibrium force");
}

}  // namespace
}  // namespace stanceplan
