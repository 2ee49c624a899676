// Lazy validation of a found plan's transitions (StanceSearch::set_transition_check): a transition
// the check rejects is dropped with its subtree, the search goes on to another plan, each
// transition is checked once, and a plan found carries the motions the check returned.
#include <gtest/gtest.h>

#include <map>
#include <utility>
#include <vector>

#include "planner/io/scenario.h"
#include "planner/search/stance_search.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/paths.h"
#include "tests/support/planned_scenario.h"

namespace stanceplan {
namespace {

struct CheckLog {
  std::vector<std::pair<int, int>> calls;  // (from, to) as indices into `seen`
  std::vector<Eigen::VectorXd> seen;       // configurations met, in order
  int index(const Eigen::VectorXd& q) {
    for (size_t i = 0; i < seen.size(); ++i)
      if (seen[i].size() == q.size() && seen[i] == q) return int(i);
    seen.push_back(q);
    return int(seen.size()) - 1;
  }
};

// A check that rejects the first transition it is asked about that adds a contact, and accepts
// every other with one sample (the configuration `to`, its forces).
TransitionCheck rejecting_first_addition(CheckLog& log, Eigen::VectorXd* rejected) {
  return [&log, rejected](const PlanStep& from, const PlanStep& to) {
    log.calls.push_back({log.index(from.q), log.index(to.q)});
    StepMotion motion;
    if (to.action == "add" && rejected->size() == 0) {
      *rejected = to.q;
      motion.status = MotionStatus::ProjectionFailed;
      motion.message = "rejected by the test";
      return motion;
    }
    motion.samples.push_back({to.q, to.forces, to.torques});
    return motion;
  };
}

TEST(TransitionCheck, ARejectedTransitionIsDroppedAndTheSearchFindsAnotherPlan) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  CheckLog log;
  Eigen::VectorXd rejected;
  StanceSearch search(scenario, test::one_process(scenario));
  search.set_transition_check(rejecting_first_addition(log, &rejected));
  std::vector<SearchEvent> failed;
  search.set_observer([&](const SearchEvent& e) {
    if (e.kind == SearchEventKind::MotionFailed) failed.push_back(e);
  });
  const SearchResult result = search.run();
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  ASSERT_EQ(failed.size(), 1u);
  EXPECT_EQ(result.transitions_dropped, 1);
  EXPECT_EQ(result.transitions_checked, int(log.calls.size()));
  const SearchNode& dropped = result.tree.at(size_t(failed[0].node));
  EXPECT_TRUE(dropped.dropped);
  EXPECT_EQ(dropped.q(), rejected);
  EXPECT_NE(failed[0].message.find("rejected by the test"), std::string::npos) << failed[0].message;
  // The plan avoids the dropped node, and every transition of it carries the check's motion.
  for (size_t i = 1; i < result.plan.steps.size(); ++i) {
    const PlanStep& step = result.plan.steps[i];
    EXPECT_NE(step.q, rejected) << "step " << i;
    ASSERT_TRUE(step.motion.has_value()) << "step " << i;
    EXPECT_EQ(step.motion->status, MotionStatus::Solved);
    ASSERT_EQ(step.motion->samples.size(), 1u);
    EXPECT_EQ(step.motion->samples[0].q, step.q);
  }
  // No transition is checked twice.
  std::map<std::pair<int, int>, int> times;
  for (const auto& call : log.calls)
    EXPECT_EQ(++times[call], 1) << call.first << "->" << call.second;
}

TEST(TransitionCheck, WithoutACheckThePlanHasNoMotion) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  const SearchResult result = StanceSearch(scenario, test::one_process(scenario)).run();
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  EXPECT_EQ(result.transitions_checked, 0);
  for (const PlanStep& step : result.plan.steps) EXPECT_FALSE(step.motion.has_value());
}

TEST(TransitionCheck, WhenEveryTransitionIsRejectedTheSearchEndsWithoutAPlan) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  SearchOptions options = test::one_process(scenario);
  options.max_nodes = 60;
  StanceSearch search(scenario, options);
  int calls = 0;
  search.set_transition_check([&calls](const PlanStep&, const PlanStep&) {
    ++calls;
    return StepMotion{MotionStatus::ProjectionFailed, "never", {}};
  });
  const SearchResult result = search.run();
  EXPECT_NE(result.status, PlanStatus::Found);
  EXPECT_GE(result.transitions_dropped, 1);
  EXPECT_EQ(result.transitions_dropped, calls);  // each failure drops the first transition tried
  EXPECT_TRUE(result.plan.steps.empty());
  ASSERT_GE(result.closest_node, 0);
  EXPECT_FALSE(result.tree[size_t(result.closest_node)].dropped);
}

// A cancel during a check ends the search Cancelled, and the transition is not dropped (the check
// failing because it was cancelled says nothing of its motion). The check's solver, given the
// search's flag, no longer runs Ipopt: a solve asked after the cancel returns at once.
TEST(TransitionCheck, ACancelDuringACheckEndsTheSearchWithoutDroppingTheTransition) {
  const Scenario scenario = load_scenario(test::source_path("scenarios/humanoid_walk.yaml"));
  StanceSearch search(scenario, test::one_process(scenario));
  SolverOptions solver = scenario.solver;
  solver.cancel = search.cancel_flag();
  const PostureSolver check_solver(scenario.scene, solver);
  PostureResult after_cancel;
  search.set_transition_check([&](const PlanStep&, const PlanStep&) {
    search.cancel();
    after_cancel = check_solver.solve(
        scenario.loaded_request(scenario.initial_stance, scenario.initial_configuration));
    return StepMotion{MotionStatus::ProjectionFailed, "cancelled", {}};
  });
  const SearchResult result = search.run();
  EXPECT_EQ(result.status, PlanStatus::Cancelled);
  EXPECT_EQ(result.transitions_dropped, 0);
  EXPECT_EQ(after_cancel.status, PostureStatus::NumericalFailure);
  EXPECT_EQ(after_cancel.message, "cancelled");
  EXPECT_EQ(after_cancel.iterations, 0);
}

}  // namespace
}  // namespace stanceplan
