// `stanceplan plan --partial`: when no plan is found the steps to the stance closest to the goal
// are written as a plan marked partial (in the file and on stderr), the exit code stays 2, and the
// partial plan certifies step by step. Interrupted runs leave a whole file or none.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>

#include "planner/io/plan_reader.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kUnreachable = test::source_path("tests/data/high_platform/unreachable.yaml");

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

TEST(PartialPlan, ANodeBudgetWritesThePathToTheClosestStanceMarkedPartial) {
  const std::string out = (test::temp_dir("partial") / "budget.json").string();
  const test::CliResult r = test::run_cli(
      {"plan", kUnreachable, "--out", out, "--max-nodes", "2", "--threads", "1", "--partial"});
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_THAT(
      r.err,
      HasSubstr("stanceplan: no plan found (node budget): no plan within 2 expanded nodes\n"));
  EXPECT_THAT(r.err, HasSubstr("stanceplan: wrote a PARTIAL plan to " + out + ": "));
  EXPECT_THAT(
      r.err,
      HasSubstr(
          " steps from the initial stance to the closest stance; it does not reach the goal\n"));
  ASSERT_TRUE(std::filesystem::exists(out));
  const json file = json::parse(text_of(out));
  EXPECT_EQ(file["partial"]["reaches_goal"], false);
  EXPECT_EQ(file["partial"]["reason"], "node budget: no plan within 2 expanded nodes");
  // The closest stance keeps both feet on the floor: the goal (both on the platform) is not
  // reached.
  const LoadedPlan plan = read_plan(out);
  EXPECT_EQ(plan.plan.partial, "node budget: no plan within 2 expanded nodes");
  ASSERT_GE(plan.plan.steps.size(), 1u);
  EXPECT_EQ(plan.plan.steps[0].action, "initial");
  const test::CliResult certified = test::run_cli({"certify", out});
  EXPECT_EQ(certified.code, 0) << certified.out << certified.err;
  EXPECT_THAT(
      certified.out,
      HasSubstr(
          "partial plan (node budget: no plan within 2 expanded nodes): every step is checked; "
          "the last stance is not the goal\n"));
  EXPECT_THAT(certified.out, HasSubstr("all checks passed"));
}

TEST(PartialPlan, WithoutTheFlagNoFileIsWritten) {
  const std::string out = (test::temp_dir("partial") / "none.json").string();
  const test::CliResult r =
      test::run_cli({"plan", kUnreachable, "--out", out, "--max-nodes", "1", "--threads", "1"});
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, Not(HasSubstr("PARTIAL")));
  EXPECT_FALSE(std::filesystem::exists(out));
}

// SIGINT once the search is expanding nodes: exit 2, "cancelled", and a whole partial plan that
// certifies; no temporary file is left beside it.
TEST(PartialPlan, SigintDuringTheSearchWritesAWholePartialPlan) {
  const std::filesystem::path dir = test::temp_dir("partial_sigint");
  const std::string out = (dir / "plan.json").string(), err = out + ".err";
  const std::string command = std::string(STANCEPLAN_BINARY) + " plan " + kUnreachable + " --out " +
                              out + " --max-nodes 1000 --threads 1 --verbose --partial 2> " + err +
                              " & pid=$!; for i in $(seq 1200); do grep -q expansion " + err +
                              " && break; sleep 0.1; done; kill -INT $pid; wait $pid";
  const int status = std::system(("bash -c '" + command + "'").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 2);
  const std::string stderr_text = text_of(err);
  EXPECT_THAT(stderr_text, HasSubstr("no plan found (cancelled)"));
  EXPECT_THAT(stderr_text, HasSubstr("wrote a PARTIAL plan"));
  EXPECT_EQ(read_plan(out).plan.partial, "cancelled: cancelled");
  const test::CliResult certified = test::run_cli({"certify", out});
  EXPECT_EQ(certified.code, 0) << certified.out << certified.err;
  std::set<std::string> files;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    files.insert(entry.path().filename().string());
  EXPECT_EQ(files, (std::set<std::string>{"plan.json", "plan.json.err"}));
}

}  // namespace
}  // namespace stanceplan
