#pragma once
// Helpers for tests of whole scenarios: certify a plan through its file, name the contacts of a
// stance. (CTest runs every test case in its own process, so each scenario is planned by one case.)
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "planner/certify/certify.h"
#include "planner/io/plan_reader.h"
#include "planner/io/plan_writer.h"
#include "planner/search/stance_search.h"
#include "tests/support/paths.h"

namespace stanceplan::test {

// A search time limit for tests that count: the node budget decides, not how busy the machine is
// (the untuned desk's 120 s ran out after 796 of its 979 calls while two compilers shared the
// 2-core machine); ctest's own timeout still bounds a test.
inline constexpr double kTestTimeLimit = 1800.0;  // s

// The scenario's own search options with one solver process and kTestTimeLimit: solver calls are
// deterministic, so tests can bound them.
inline SearchOptions one_process(const Scenario& scenario) {
  SearchOptions options = scenario.search;
  options.threads = 1;
  options.time_limit_s = kTestTimeLimit;
  return options;
}

inline SearchResult plan_with_one_process(const Scenario& scenario) {
  return StanceSearch(scenario, one_process(scenario)).run();
}

// Certifies a plan through its file, as `stanceplan certify` would, and reports every failed check.
inline void expect_certified(const Scenario& scenario, const SearchResult& result,
                             const std::string& name) {
  ASSERT_EQ(result.status, PlanStatus::Found) << result.message;
  const std::string path = (temp_dir("scenarios") / (name + ".json")).string();
  write_plan(result.plan, scenario, path);
  const CertifyReport report = certify(read_plan(path));
  for (const CheckResult& c : report.checks)
    EXPECT_TRUE(c.passed()) << c.name << " " << c.worst << " at step " << c.step << ": "
                            << c.detail;
  EXPECT_TRUE(report.passed());
}

// A fixture with the walk (scenarios/humanoid_walk.yaml) planned once per test suite, with one
// solver process: for tests that need a real plan.
class PlannedWalk : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    scenario_ = new Scenario(load_scenario(source_path("scenarios/humanoid_walk.yaml")));
    SearchOptions options = scenario_->search;
    options.threads = 1;
    result_ = new SearchResult(StanceSearch(*scenario_, options).run());
  }
  static void TearDownTestSuite() {
    delete result_;
    delete scenario_;
    result_ = nullptr;
    scenario_ = nullptr;
  }
  static inline Scenario* scenario_ = nullptr;
  static inline SearchResult* result_ = nullptr;
};

// The contacts of a stance as "s1 id-s2 id" strings, e.g. "cyl/bottom-env/platform_a".
inline std::set<std::string> stance_ids(const Scenario& scenario, const Stance& stance) {
  std::set<std::string> ids;
  const Scene& scene = scenario.scene;
  for (const Contact& c : stance.contacts())
    ids.insert(scene.surfaces.id(scene.system, c.s1) + "-" + scene.surfaces.id(scene.system, c.s2));
  return ids;
}

}  // namespace stanceplan::test
