// `stanceplan certify` accepts a real plan and rejects tampered ones, naming the failing check.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

using test::CliResult;
CliResult run(std::vector<std::string> args) {
  return test::run_cli(std::move(args));
}

class Certify : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    path_ = new std::string((test::temp_dir("certify") / "certify_walk.json").string());
    const CliResult r = run({"plan", test::source_path("scenarios/humanoid_walk.yaml"), "--out",
                             *path_, "--threads", "1"});
    ASSERT_EQ(r.code, 0) << r.err;
    std::ifstream in(*path_);
    plan_ = new json(json::parse(in));
  }
  static void TearDownTestSuite() {
    delete plan_;
    delete path_;
  }
  // Writes a tampered copy and certifies it.
  static CliResult certify_modified(const std::function<void(json&)>& change,
                                    const std::string& name) {
    json copy = *plan_;
    change(copy);
    const std::string path = (test::temp_dir("certify") / ("tampered_" + name + ".json")).string();
    std::ofstream(path) << copy.dump();
    return run({"certify", path});
  }
  static std::string* path_;
  static json* plan_;
};
std::string* Certify::path_ = nullptr;
json* Certify::plan_ = nullptr;

TEST_F(Certify, TheRealPlanPasses) {
  const CliResult r = run({"certify", *path_});
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("all checks passed"));
  EXPECT_THAT(r.out, HasSubstr("torque consistency"));
}

TEST_F(Certify, AJointPastItsLimitFails) {
  const CliResult r = certify_modified(
      [](json& p) { p["steps"][3]["configuration"]["robot"]["joints"]["l_knee_p"] = 2.7; },
      "limit");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("certification failed: joint limits at step 3: robot/l_knee_p"));
}

TEST_F(Certify, AForceScaledByTwoFails) {
  const CliResult r = certify_modified(
      [](json& p) {
        for (auto& v : p["steps"][2]["forces"][0]["force_world"]) v = v.get<double>() * 2.0;
      },
      "force");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("certification failed: equilibrium force at step 2: robot"));
}

TEST_F(Certify, AStepRemovedFromTheSequenceFails) {
  const CliResult r = certify_modified([](json& p) { p["steps"].erase(4); }, "step");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("certification failed: sequence at step 4"));
}

TEST_F(Certify, AContactSurfaceMovedFiveCentimetresOffFails) {
  const CliResult r = certify_modified(
      [](json& p) {
        for (auto& s : p["surfaces"])
          if (s["id"] == "robot/l_sole") {
            for (auto& v : s["vertices"]) v[2] = v[2].get<double>() + 0.05;  // 5 cm into the foot
            s["origin"][2] = s["origin"][2].get<double>() + 0.05;
          }
      },
      "vertex");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("certification failed: contact plane at step"));
}

TEST_F(Certify, AForcePointMovedOffItsVertexFails) {
  const CliResult r = certify_modified(
      [](json& p) {
        auto& point = p["steps"][1]["forces"][2]["point_world"];
        point[0] = point[0].get<double>() + 0.05;
      },
      "point");
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("certification failed: force points at step 1"));
}

TEST_F(Certify, AnUnreadablePlanIsBadInput) {
  const CliResult r = run({"certify", "/nonexistent/plan.json"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "stanceplan: error: /nonexistent/plan.json: no such file\n");
}

TEST(PlanCommand, AnUnreachableGoalExitsTwoWithAReason) {
  const CliResult r =
      run({"plan", test::source_path("tests/data/high_platform/unreachable.yaml"), "--out",
           (test::temp_dir("certify") / "unreachable.json").string(), "--max-nodes", "4"});
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("stanceplan: no plan found ("));
  EXPECT_THAT(r.err, HasSubstr("closest stance to the goal: {"));
}

}  // namespace
}  // namespace stanceplan

namespace stanceplan {
namespace {

// SIGINT during planning stops the search cleanly: exit 2, "cancelled", and no plan file.
TEST(PlanCommand, SigintStopsTheSearchCleanly) {
  const std::string out = (test::temp_dir("sigint") / "plan.json").string();
  const std::string command = std::string(STANCEPLAN_BINARY) + " plan " +
                              test::source_path("tests/data/high_platform/unreachable.yaml") +
                              " --out " + out + " --max-nodes 1000 2> " + out +
                              ".err & pid=$!; sleep 1; kill -INT $pid; wait $pid";
  const int status = std::system(("bash -c '" + command + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  std::ifstream err(out + ".err");
  const std::string text((std::istreambuf_iterator<char>(err)), {});
  EXPECT_THAT(text, HasSubstr("no plan found (cancelled)"));
  EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace stanceplan

namespace stanceplan {
namespace {

// Output written before the solver processes are forked appears once, not once per process,
// when stdout is a file (fully buffered).
TEST(PlanCommand, OutputBeforeTheWorkersForkIsWrittenOnce) {
  const std::filesystem::path dir = test::temp_dir("fork_output");
  const std::string command =
      std::string(STANCEPLAN_BINARY) + " " + test::source_path("scenarios/humanoid_walk.yaml") +
      " --headless --threads 2 --out " + (dir / "out").string() +
      " --no-rejected-snapshots --no-motion > " + (dir / "stdout.txt").string() + " 2>&1";
  ASSERT_EQ(std::system(command.c_str()), 0);
  std::ifstream in(dir / "stdout.txt");
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  size_t count = 0;
  for (size_t at = text.find("stanceplan: planning"); at != std::string::npos;
       at = text.find("stanceplan: planning", at + 1))
    ++count;
  EXPECT_EQ(count, 1u) << text;
}

}  // namespace
}  // namespace stanceplan
