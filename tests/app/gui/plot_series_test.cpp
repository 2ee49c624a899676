// plot_series: the numbers behind the inspector's plots, from hand-made event streams (and the
// humanoid walk's scene, for contact names and joint effort limits).
#include "app/gui/plot_series.h"

#include <gtest/gtest.h>

#include <chrono>

#include "app/gui/node_details.h"
#include "app/live/plan_session.h"
#include "planner/io/scenario.h"
#include "tests/support/paths.h"

namespace stanceplan::gui {
namespace {

SearchEvent candidate(int number, int parent, int node, bool accepted, double ms, int iterations) {
  SearchEvent e;
  e.number = number;
  e.kind = SearchEventKind::Candidate;
  e.parent = parent;
  e.node = accepted ? node : -1;
  e.accepted = accepted;
  e.status = accepted ? PostureStatus::Solved : PostureStatus::Infeasible;
  e.time_ms = ms;
  e.iterations = iterations;
  return e;
}

SearchEvent of_kind(int number, SearchEventKind kind, int node, int milestone) {
  SearchEvent e;
  e.number = number;
  e.kind = kind;
  e.node = node;
  e.milestone = milestone;
  return e;
}

// root 0; 0 expanded -> 1 accepted, one rejected, 2 accepted; 1 expanded -> 3 accepted, which
// reaches milestone 1 and is the goal. Plan path: 0, 1, 3 (events 0, 2, 6).
std::vector<SearchEvent> story() {
  return {candidate(0, -1, 0, true, 12.5, 40),         of_kind(1, SearchEventKind::Expansion, 0, 0),
          candidate(2, 0, 1, true, 3.0, 11),           candidate(3, 0, -1, false, 30.0, 200),
          candidate(4, 0, 2, true, 4.0, 12),           of_kind(5, SearchEventKind::Expansion, 1, 0),
          candidate(6, 1, 3, true, 5.0, 13),           of_kind(7, SearchEventKind::Milestone, 3, 1),
          of_kind(8, SearchEventKind::PlanFound, 3, 1)};
}

SearchTree tree_of(const std::vector<SearchEvent>& events) {
  SearchTree tree;
  for (size_t i = 0; i < events.size(); ++i) tree.add(events[i], i);
  return tree;
}

Plan plan_of_steps(size_t steps) {
  Plan plan;
  plan.steps.resize(steps);
  return plan;
}

const Scenario& walk() {
  static const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  return scenario;
}

// robot surface `index` (l_sole, r_sole, l_palm ...) on the floor.
PlanContact on_floor(int index, bool loaded = true) {
  return {Contact{SurfaceRef{0, index}, SurfaceRef{1, 0}}, loaded};
}

std::string name_of(const PlanContact& c) {
  const Scene& scene = walk().scene;
  return scene.surfaces.get(c.contact.s1).name + " on " + scene.surfaces.get(c.contact.s2).name;
}

VertexForce force_on(int contact, double z) {
  VertexForce f;
  f.contact = contact;
  f.force_W = Eigen::Vector3d(1.0, -2.0, z);
  return f;
}

TEST(PlotSeries, EveryCandidateSolveIsAPointFlaggedByItsOutcome) {
  const std::vector<SearchEvent> events = story();
  const SearchSeries s = search_series(events);
  // Accepted: the root and nodes 1, 2, 3; expansions and milestones are no solves.
  ASSERT_EQ(s.accepted_time_ms.points.size(), 4u);
  ASSERT_EQ(s.rejected_time_ms.points.size(), 1u);
  EXPECT_EQ(s.accepted_iterations.points.size(), 4u);
  ASSERT_EQ(s.rejected_iterations.points.size(), 1u);
  const PlotPoint& rejected = s.rejected_time_ms.points[0];
  EXPECT_EQ(rejected.x, 3.0);
  EXPECT_EQ(rejected.y, 30.0);
  EXPECT_EQ(rejected.event, 3);
  EXPECT_EQ(s.rejected_iterations.points[0].y, 200.0);
  std::vector<long> accepted_events;
  for (const PlotPoint& p : s.accepted_time_ms.points) accepted_events.push_back(p.event);
  EXPECT_EQ(accepted_events, (std::vector<long>{0, 2, 4, 6}));
  EXPECT_EQ(s.accepted_time_ms.points[0].y, 12.5);
  EXPECT_EQ(s.accepted_iterations.points[3].y, 13.0);
  EXPECT_EQ(s.accepted_iterations.points[3].x, 6.0);
}

TEST(PlotSeries, XIsTheEventNumberAndEventTheIndexInTheStream) {
  // A stream whose numbering does not start at 0 (a mirror joined late, or a rerun): x follows
  // SearchEvent::number, while `event` stays the index used to select the event.
  std::vector<SearchEvent> events = {candidate(40, -1, 0, true, 1.0, 5),
                                     candidate(41, 0, -1, false, 2.0, 6)};
  const SearchSeries s = search_series(events);
  ASSERT_EQ(s.rejected_time_ms.points.size(), 1u);
  EXPECT_EQ(s.rejected_time_ms.points[0].x, 41.0);
  EXPECT_EQ(s.rejected_time_ms.points[0].event, 1);
}

TEST(PlotSeries, TheMilestoneStaircaseKeepsEachLevelsFirstEventAndTheNewest) {
  std::vector<SearchEvent> events = story();
  events.push_back(of_kind(9, SearchEventKind::Failure, 3, 0));  // carries no milestone
  const SearchSeries s = search_series(events);
  // Level 0 from event 0 to 6, level 1 from the milestone event 7 to the newest (8).
  std::vector<std::pair<double, double>> stairs;
  for (const PlotPoint& p : s.milestone_target.points) stairs.push_back({p.x, p.y});
  EXPECT_EQ(stairs, (std::vector<std::pair<double, double>>{{0, 0}, {6, 0}, {7, 1}, {8, 1}}));
  ASSERT_EQ(s.milestones_reached.points.size(), 2u);
  EXPECT_EQ(s.milestones_reached.points[0].event, 7);
  EXPECT_EQ(s.milestones_reached.points[0].y, 1.0);
  EXPECT_EQ(s.milestones_reached.points[0].note, "milestone reached");
  EXPECT_EQ(s.milestones_reached.points[1].event, 8);
  EXPECT_EQ(s.milestones_reached.points[1].note, "goal reached");
}

TEST(PlotSeries, PlanStepKIsThePlanPathsKthNodeAndTheEventThatMadeIt) {
  const std::vector<SearchEvent> events = story();
  const SearchTree tree = tree_of(events);
  const PlanSeries s = plan_series(walk().scene, events, tree, plan_of_steps(3));
  EXPECT_EQ(s.nodes, (std::vector<int>{0, 1, 3}));
  ASSERT_EQ(s.worst_torque_ratio.points.size(), 3u);
  for (size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(s.worst_torque_ratio.points[k].x, double(k));
    EXPECT_EQ(s.worst_torque_ratio.points[k].event, long(tree.node(s.nodes[k])->event));
  }
  // Node 2 (made by event 4) is off the plan, so no step shows its event.
  EXPECT_EQ(s.worst_torque_ratio.points[2].event, 6);
}

TEST(PlotSeries, NoPlanPathMeansNoPlanPoints) {
  std::vector<SearchEvent> events = story();
  events.pop_back();  // no PlanFound
  const PlanSeries s = plan_series(walk().scene, events, tree_of(events), plan_of_steps(3));
  EXPECT_TRUE(s.nodes.empty());
  EXPECT_TRUE(s.worst_torque_ratio.points.empty());
  EXPECT_TRUE(s.contact_force_z.empty());
}

TEST(PlotSeries, StepsBeyondThePlanPathAreLeftOut) {
  const std::vector<SearchEvent> events = story();
  const PlanSeries longer = plan_series(walk().scene, events, tree_of(events), plan_of_steps(5));
  EXPECT_EQ(longer.worst_torque_ratio.points.size(), 3u);
  const PlanSeries shorter = plan_series(walk().scene, events, tree_of(events), plan_of_steps(2));
  EXPECT_EQ(shorter.nodes, (std::vector<int>{0, 1}));
}

TEST(PlotSeries, TheWorstTorqueRatioIsNodeDetailsValueAndNamesItsJoint) {
  const Scene& scene = walk().scene;
  const Model& model = *scene.system.entity(0).model;
  // The last dof whose joint states an effort limit carries 80 % of it, one other 30 %.
  int loaded = -1, other = -1;
  for (int k = 0; k < model.num_dofs(); ++k)
    if (model.joints[model.dof_joints[k]].effort > 0.0) (loaded >= 0 ? other : loaded) = k;
  ASSERT_GE(loaded, 0);
  ASSERT_GE(other, 0);
  std::vector<SearchEvent> events = story();
  Eigen::VectorXd tau = Eigen::VectorXd::Zero(model.num_dofs());
  tau[loaded] = -0.8 * model.joints[model.dof_joints[loaded]].effort;  // sign does not matter
  tau[other] = 0.3 * model.joints[model.dof_joints[other]].effort;
  events[2].torques = {tau};  // node 1 = plan step 1
  const PlanSeries s = plan_series(scene, events, tree_of(events), plan_of_steps(3));
  ASSERT_EQ(s.worst_torque_ratio.points.size(), 3u);
  const PlotPoint& step1 = s.worst_torque_ratio.points[1];
  EXPECT_NEAR(step1.y, 0.8, 1e-12);
  EXPECT_DOUBLE_EQ(step1.y, node_details(scene, events[2]).worst_torque_ratio);
  EXPECT_EQ(step1.note, "robot " + model.joints[model.dof_joints[loaded]].name);
  EXPECT_EQ(s.worst_torque_ratio.points[0].y, 0.0);  // no torques published: nothing to plot
  EXPECT_EQ(s.worst_torque_ratio.points[0].note, "");
}

TEST(PlotSeries, EachContactIsASeriesOfVerticalForcesWithNoPointWhereItIsAbsent) {
  std::vector<SearchEvent> events = story();
  // Step 0: both soles (two vertex forces on the left one); step 1: the left palm added, still
  // unloaded; step 2: the right sole gone.
  events[0].contacts = {on_floor(0), on_floor(1)};
  events[0].forces = {force_on(0, 100.0), force_on(0, 50.0), force_on(1, 200.0)};
  events[2].contacts = {on_floor(0), on_floor(1), on_floor(2, false)};
  events[2].forces = {force_on(0, 120.0), force_on(1, 230.0)};
  events[6].contacts = {on_floor(2), on_floor(0)};
  events[6].forces = {force_on(0, 90.0), force_on(1, 260.0)};
  const PlanSeries s = plan_series(walk().scene, events, tree_of(events), plan_of_steps(3));
  ASSERT_EQ(s.contact_force_z.size(), 3u);
  const PlotSeries &left = s.contact_force_z[0], &right = s.contact_force_z[1],
                   &palm = s.contact_force_z[2];
  EXPECT_EQ(left.name, name_of(on_floor(0)));
  EXPECT_EQ(right.name, name_of(on_floor(1)));
  EXPECT_EQ(palm.name, name_of(on_floor(2)));
  ASSERT_EQ(left.points.size(), 3u);
  EXPECT_EQ(left.points[0].y, 150.0);  // the vertex forces summed
  EXPECT_EQ(left.points[2].y, 260.0);  // forces index the step's own contact list
  ASSERT_EQ(right.points.size(), 2u);  // absent at step 2
  EXPECT_EQ(right.points[1].x, 1.0);
  EXPECT_EQ(right.points[1].y, 230.0);
  ASSERT_EQ(palm.points.size(), 2u);  // touching unloaded at step 1: a point at zero
  EXPECT_EQ(palm.points[0].x, 1.0);
  EXPECT_EQ(palm.points[0].y, 0.0);
  EXPECT_EQ(palm.points[0].note, "touching, unloaded");
  EXPECT_EQ(palm.points[1].y, 90.0);
  EXPECT_EQ(palm.points[1].event, 6);
}

// The whole walk, searched for real: each plotted step carries the figures of the plan's own step
// (the plan is the tree's path, so its torques and forces are the events').
TEST(PlotSeries, TheWalksPlanPlotsMatchThePlanItself) {
  using namespace std::chrono_literals;
  SearchOptions options = walk().search;
  options.threads = 1;
  app::PlanSession session(walk(), options);
  session.start();
  ASSERT_TRUE(session.wait_until_finished(120s));
  std::vector<SearchEvent> events;
  SearchTree tree;
  for (size_t i = 0; i < session.event_count(); ++i) {
    events.push_back(session.event(i));
    tree.add(events.back(), i);
  }
  const SearchResult result = *session.result();
  ASSERT_EQ(result.status, PlanStatus::Found);
  const Plan& plan = result.plan;
  const PlanSeries s = plan_series(walk().scene, events, tree, plan);
  ASSERT_EQ(s.worst_torque_ratio.points.size(), plan.steps.size());
  ASSERT_GE(s.contact_force_z.size(), 2u);  // both soles
  for (size_t k = 0; k < plan.steps.size(); ++k) {
    SearchEvent as_step;  // the plan's step dressed as an event, for node_details
    as_step.torques = plan.steps[k].torques;
    as_step.contacts = plan.steps[k].contacts;
    as_step.forces = plan.steps[k].forces;
    const NodeDetails d = node_details(walk().scene, as_step);
    EXPECT_NEAR(s.worst_torque_ratio.points[k].y, d.worst_torque_ratio, 1e-9) << "step " << k;
    double plotted_z = 0.0;  // the step's points over every contact series
    for (const PlotSeries& c : s.contact_force_z)
      for (const PlotPoint& p : c.points)
        if (p.x == double(k)) plotted_z += p.y;
    EXPECT_NEAR(plotted_z, d.total_force_z, 1e-6 * (1.0 + d.total_force_z)) << "step " << k;
  }
}

}  // namespace
}  // namespace stanceplan::gui
