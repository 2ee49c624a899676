// The paper's third scenario (docs/METHOD.md section 5), planned within its own budget and
// certified: scenarios/dual_arm_cylinder.yaml, a hand-over of a faceted cylinder between two fixed
// arms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "planner/model/kinematics.h"
#include "planner/search/stance_search.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"
#include "tests/support/scenario_motion.h"

namespace stanceplan {
namespace {

int pads_of(const std::set<std::string>& ids, const std::string& arm) {
  return int(std::count_if(ids.begin(), ids.end(),
                           [&](const std::string& id) { return id.rfind(arm + "/pad_", 0) == 0; }));
}

// Plans with the scenario's own options (budgets included) and certifies the plan; then the
// hand-over itself.
TEST(DualArm, PlansCertifiesAndArm1HandsTheCylinderOverToArm2InTheAir) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/dual_arm_cylinder.yaml"));
  const SearchResult result = StanceSearch(scenario, scenario.search).run();
  test::expect_certified(scenario, result, "dual_arm_cylinder");
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  // The motion between the steps: every step moves and certifies sample by sample.
  test::expect_motion_certified(scenario, result, "dual_arm_cylinder");
  EXPECT_LE(result.nodes_expanded, scenario.search.max_nodes);
  const auto& steps = result.plan.steps;
  ASSERT_GE(steps.size(), 9u);  // 2 pads on, off A, 2 pads on, 2 pads off, on B, 2 pads off
  EXPECT_EQ(test::stance_ids(scenario, steps.front().stance),
            std::set<std::string>{"cyl/bottom-env/platform_a"});
  EXPECT_EQ(test::stance_ids(scenario, steps.back().stance),
            std::set<std::string>{"cyl/bottom-env/platform_b"});
  bool handed_over = false;
  for (size_t i = 0; i < steps.size(); ++i) {
    const auto ids = test::stance_ids(scenario, steps[i].stance);
    const bool on_a = ids.count("cyl/bottom-env/platform_a") > 0,
               on_b = ids.count("cyl/bottom-env/platform_b") > 0;
    const int arm1 = pads_of(ids, "arm1"), arm2 = pads_of(ids, "arm2");
    // Off the platforms the cylinder is held by the pads alone: one arm's grasp, a squeeze by one
    // pad of each arm, or (since the solver starts from balanced forces) a single pad carrying it
    // from below, tilted to the edge of its friction cone; the statics of every step are certified
    // above.
    EXPECT_TRUE(on_a || on_b || arm1 + arm2 >= 1) << "step " << i;
    if (!on_a && !on_b && arm1 + arm2 == 1) {
      for (const VertexForce& f : steps[i].forces)  // the pad pushes the cylinder up
        EXPECT_GT(-f.force_W.z(), 0.0) << "step " << i;
    }
    // Each arm only touches the cylinder where it can reach it.
    EXPECT_TRUE(!on_a || arm2 == 0) << "step " << i;
    EXPECT_TRUE(!on_b || arm1 == 0) << "step " << i;
    handed_over |= !on_a && !on_b && arm1 > 0 && arm2 > 0;
  }
  EXPECT_TRUE(handed_over) << "no step where both arms hold the cylinder in the air";
  // The cylinder ends on B: centre near B's (0.55, 0.05), bottom on B's top face (z = 0.2).
  const int cyl = scenario.scene.system.find_entity("cyl");
  const Eigen::Vector3d p_end = steps.back().q.segment<3>(scenario.scene.system.offset(cyl));
  EXPECT_NEAR(p_end.x(), 0.55, 0.13);
  EXPECT_NEAR(p_end.y(), 0.05, 0.13);
  EXPECT_NEAR(p_end.z(), 0.31, 1e-3);
}

// "Reachable only by arm 1 / arm 2", checked with a bound that holds for every configuration: a
// pad vertex is never farther from the shoulder pitch axis point than the sum of the joint offsets
// after it, the fingers' full travel and the vertex's distance from its link origin; the cylinder's
// nearest point is at least its centre's distance minus the prism's circumradius.
TEST(DualArm, EachPlatformIsOutOfTheOtherArmsReach) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/dual_arm_cylinder.yaml"));
  const Scene& scene = scenario.scene;
  const System& system = scene.system;
  const Entity& arm = system.entity(system.find_entity("arm1"));
  const Model& model = *arm.model;
  double chain = 0.0;
  const Surface& pad = scene.surfaces.get(*scene.surfaces.find(system, "arm1/pad_l"));
  int link = pad.link;
  while (model.links[link].name != "upper_arm") {
    const Joint& joint = model.joints[model.links[link].parent_joint];
    chain +=
        joint.T_PJ.translation().norm() + (joint.type == JointType::Prismatic ? joint.upper : 0.0);
    link = model.links[link].parent_link;
  }
  double vertex = 0.0;
  for (const Eigen::Vector3d& v : pad.vertices_L()) vertex = std::max(vertex, v.norm());
  const double reach = chain + vertex;
  EXPECT_NEAR(reach, 0.831, 0.01);
  const double circumradius = 0.06 / std::cos(M_PI / 12);
  const auto data = system_kinematics(system, scenario.initial_configuration);
  auto shoulder = [&](const std::string& name) {
    const int e = system.find_entity(name);
    return data[e].T_WL[system.entity(e).model->find_link("upper_arm")].translation();
  };
  const Eigen::Vector3d a(-0.55, 0.05, 0.31), b(0.55, 0.05, 0.31);  // the cylinder on A, on B
  EXPECT_GT((shoulder("arm2") - a).norm() - circumradius, reach + 0.04);
  EXPECT_GT((shoulder("arm1") - b).norm() - circumradius, reach + 0.04);
  EXPECT_LT((shoulder("arm1") - a).norm() + circumradius, reach);
  EXPECT_LT((shoulder("arm2") - b).norm() + circumradius, reach);
}

}  // namespace
}  // namespace stanceplan
