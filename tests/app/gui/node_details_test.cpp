// node_details: the inspector's figures for a real solved posture (the walk's initial stance).
#include "app/gui/node_details.h"

#include <gtest/gtest.h>

#include <chrono>
#include <optional>

#include "app/live/plan_session.h"
#include "tests/support/paths.h"

namespace stanceplan::gui {
namespace {

using namespace std::chrono_literals;

double robot_mass(const Scene& scene) {
  double m = 0.0;
  for (int e = 0; e < scene.system.num_entities(); ++e)
    if (scene.system.entity(e).kind == EntityKind::FloatingRobot)
      m += scene.system.entity(e).model->total_mass;
  return m;
}

TEST(NodeDetails, TheRootPostureCarriesTheRobotsWeightWithinItsTorqueLimits) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  SearchOptions options = scenario.search;
  options.threads = 1;
  app::PlanSession session(scenario, options);
  session.gate().pause();
  session.gate().step(1);
  session.start();
  ASSERT_TRUE(session.wait_for_event(0, 60s));
  const SearchEvent root = session.event(0);
  ASSERT_EQ(root.kind, SearchEventKind::Candidate);
  ASSERT_TRUE(root.accepted);
  const NodeDetails d = node_details(scenario.scene, root);

  ASSERT_EQ(d.contacts.size(), 2u);
  for (const ContactRow& c : d.contacts) {
    EXPECT_TRUE(c.loaded);
    EXPECT_GT(c.vertices, 0);
    EXPECT_GT(c.force_W.z(), 0.0) << c.name;
  }
  EXPECT_NE(d.contacts[0].name.find(" on floor"), std::string::npos) << d.contacts[0].name;
  // E16: the contact forces hold the weight (the only other load is gravity).
  const double weight = robot_mass(scenario.scene) * scenario.scene.gravity.norm();
  EXPECT_NEAR(d.total_force_z, weight, 2e-3 * weight);
  // E19 holds at a solved posture: every torque within its effort limit.
  ASSERT_FALSE(d.torques.empty());
  EXPECT_GT(d.worst_torque_ratio, 0.0);
  EXPECT_LE(d.worst_torque_ratio, 1.0 + 1e-6);
  EXPECT_EQ(static_cast<int>(d.torques.size()), scenario.scene.system.entity(0).model->num_dofs());
  // Residuals come largest first, and a solved posture has small ones.
  ASSERT_FALSE(d.residuals.empty());
  for (size_t i = 1; i < d.residuals.size(); ++i)
    EXPECT_GE(d.residuals[i - 1].value, d.residuals[i].value);
  EXPECT_LT(d.residuals.front().value, 1e-3);
  EXPECT_GT(root.iterations, 0);
  // The configuration entry by entry: the floating base first, then every joint.
  ASSERT_EQ(static_cast<int>(d.configuration.size()), scenario.scene.system.nq());
  EXPECT_EQ(d.configuration[0].name, "base x");
  EXPECT_EQ(d.configuration[6].name, "base qz");
  EXPECT_EQ(d.configuration[7].name, d.torques[0].joint);
  for (size_t i = 0; i < d.configuration.size(); ++i)
    EXPECT_EQ(d.configuration[i].value, root.q[i]);
}

// A milestone event shows the stance its node realised: the loaded contacts with their forces
// (they once showed "Contacts: none").
TEST(NodeDetails, AMilestoneEventListsItsNodesLoadedContacts) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  SearchOptions options = scenario.search;
  options.threads = 1;
  app::PlanSession session(scenario, options);
  session.start();
  std::optional<SearchEvent> milestone;
  for (size_t i = 0; !milestone && session.wait_for_event(i, 60s); ++i)
    if (session.event(i).kind == SearchEventKind::Milestone) milestone = session.event(i);
  ASSERT_TRUE(milestone.has_value()) << "the walk reaches milestones";
  const NodeDetails d = node_details(scenario.scene, *milestone);
  ASSERT_FALSE(d.contacts.empty());
  int loaded = 0;
  for (const ContactRow& c : d.contacts) loaded += c.loaded ? 1 : 0;
  EXPECT_GE(loaded, 1);
  // Every contact of the node's stance is listed (with the contact its transition broke or made,
  // touching without force, when there is one).
  EXPECT_GE(d.contacts.size(), milestone->stance.contacts().size());
  for (const Contact& c : milestone->stance.contacts()) {
    bool listed = false;
    for (const PlanContact& shown : milestone->contacts) listed |= shown.contact.same_surfaces(c);
    EXPECT_TRUE(listed);
  }
  const double weight = robot_mass(scenario.scene) * scenario.scene.gravity.norm();
  EXPECT_NEAR(d.total_force_z, weight, 2e-3 * weight);
  EXPECT_FALSE(d.torques.empty());
}

}  // namespace
}  // namespace stanceplan::gui
