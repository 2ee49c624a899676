// The untuned scenarios (scenarios/untuned/README.md), the measure of bench/untuned_bench.cpp:
// every file loads, and each stays untuned (a file tuned to pass would make the benchmark measure
// the tuning). Loading only: no solve, no search.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

#include "planner/io/scenario.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

std::vector<std::string> untuned_files() {
  std::vector<std::string> files;
  for (const auto& entry :
       std::filesystem::directory_iterator(test::source_path("scenarios/untuned")))
    if (entry.path().extension() == ".yaml") files.push_back(entry.path().string());
  std::sort(files.begin(), files.end());
  return files;
}

std::string stem(const std::string& path) {
  return std::filesystem::path(path).stem().string();
}

TEST(UntunedScenarios, TheFolderHoldsTheFiveTasks) {
  std::vector<std::string> names;
  for (const std::string& f : untuned_files()) names.push_back(stem(f));
  EXPECT_EQ(names, (std::vector<std::string>{"desk", "dual_arm_handover", "side_step", "stairs",
                                             "walk_turn"}));
}

TEST(UntunedScenarios, EveryFileLoads) {
  for (const std::string& f : untuned_files()) {
    SCOPED_TRACE(f);
    Scenario s;
    ASSERT_NO_THROW(s = load_scenario(f));
    EXPECT_FALSE(s.goal_stance.empty());
    EXPECT_FALSE(s.milestones.empty());
  }
}

// Only the time budget (kept short, so that the benchmark ends) and the contact families differ
// from the defaults; the solver keeps its own too.
TEST(UntunedScenarios, SearchAndSolverKeepTheirDefaults) {
  const SearchOptions d;
  const SolverOptions solver;
  for (const std::string& f : untuned_files()) {
    SCOPED_TRACE(f);
    const Scenario s = load_scenario(f);
    const SearchOptions& o = s.search;
    EXPECT_LE(o.time_limit_s, 180.0);
    EXPECT_EQ(o.max_nodes, d.max_nodes);
    EXPECT_EQ(o.milestone_tolerance, d.milestone_tolerance);
    EXPECT_EQ(o.threads, d.threads);
    EXPECT_EQ(o.contact_reach, d.contact_reach);
    EXPECT_EQ(o.self_contacts, d.self_contacts);
    EXPECT_EQ(o.min_contacts, d.min_contacts);
    EXPECT_TRUE(o.last_contacts.empty());
    EXPECT_EQ(o.placement_tolerance, d.placement_tolerance);
    EXPECT_EQ(o.orientation_tolerance, d.orientation_tolerance);
    EXPECT_EQ(o.stance_weight, d.stance_weight);
    EXPECT_EQ(o.max_retries, d.max_retries);
    EXPECT_EQ(s.solver.max_iterations, solver.max_iterations);
    EXPECT_EQ(s.solver.tolerance, solver.tolerance);
  }
}

// A family is a pattern with a wildcard on both sides (robot/* against env/*), never one chosen
// surface pair.
TEST(UntunedScenarios, ContactPairsAreWholeFamilies) {
  auto wild = [](const std::string& p) { return p.find('*') != std::string::npos; };
  for (const std::string& f : untuned_files()) {
    SCOPED_TRACE(f);
    const Scenario s = load_scenario(f);
    EXPECT_FALSE(s.search.contact_pairs.empty());
    for (const auto& [s1, s2] : s.search.contact_pairs) {
      EXPECT_TRUE(wild(s1)) << s1;
      EXPECT_TRUE(wild(s2)) << s2;
    }
  }
}

// True when entry i of q is a root position (the first three entries of a floating entity).
bool is_base_position(const System& system, int i) {
  for (int e = 0; e < system.num_entities(); ++e)
    if (system.entity(e).floating() && i >= system.offset(e) && i < system.offset(e) + 3)
      return true;
  return false;
}

// Coarse guides: a milestone states base positions and nothing else (no joint angles, no
// orientation, no contact phase, no tolerance of its own).
TEST(UntunedScenarios, MilestonesStateOnlyBasePositions) {
  for (const std::string& f : untuned_files()) {
    SCOPED_TRACE(f);
    const Scenario s = load_scenario(f);
    for (size_t m = 0; m < s.milestones.size(); ++m) {
      SCOPED_TRACE("milestone " + std::to_string(m));
      const Eigen::VectorXd& mask = s.milestone_masks[m];
      EXPECT_GT(mask.sum(), 0.0);
      for (int i = 0; i < int(mask.size()); ++i)
        if (mask[i] > 0.0) {
          EXPECT_TRUE(is_base_position(s.scene.system, i)) << "entry " << i;
        }
      EXPECT_TRUE(s.milestone_contact_pairs[m].empty());
      EXPECT_EQ(s.milestone_tolerances[m], 0.0);
    }
  }
}

}  // namespace
}  // namespace stanceplan
