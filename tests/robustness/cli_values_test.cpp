// Bad command-line values exit 1 with a message naming the option, what was expected and what was
// found; --help documents the exit codes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

// The error line of a usage fault (the first line of stderr).
std::string usage_error(const std::vector<std::string>& args) {
  const test::CliResult r = test::run_cli(args);
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_THAT(r.err, HasSubstr("Run 'stanceplan --help' for usage."));
  return r.err.substr(0, r.err.find('\n'));
}

const std::string kScenario = test::source_path("scenarios/humanoid_walk.yaml");

TEST(CliValues, ThreadsMustBeAWholeNumberFromOneTo256) {
  for (const std::string value : {"-1", "0", "abc", "2.5", "257", "99999999999999999999"})
    EXPECT_EQ(
        usage_error({"plan", kScenario, "--threads", value}),
        "stanceplan: --threads: expected a whole number from 1 to 256, found \"" + value + "\"");
}

TEST(CliValues, TheTimeLimitMustBeAFinitePositiveNumber) {
  for (const std::string value : {"-5", "0", "nan", "inf", "ten"})
    EXPECT_EQ(usage_error({"plan", kScenario, "--time-limit", value}),
              "stanceplan: --time-limit: expected a finite number > 0, found \"" + value + "\"");
}

TEST(CliValues, MaxNodesMustBeAWholeNumber) {
  for (const std::string value : {"0", "1e3", "-4"})
    EXPECT_EQ(usage_error({"plan", kScenario, "--max-nodes", value}),
              "stanceplan: --max-nodes: expected a whole number from 1 to 100000000, found \"" +
                  value + "\"");
}

TEST(CliValues, RenderSizeViewAndCameraAreChecked) {
  for (const std::string value : {"10x10", "abc", "640x", "640x360x2", "-640x360", "99999x99999"})
    EXPECT_EQ(
        usage_error({"render", "plan.json", "--out", "frames", "--size", value}),
        "stanceplan: --size: expected WIDTHxHEIGHT between 16 and 8192, found \"" + value + "\"");
  EXPECT_EQ(usage_error({"render", "plan.json", "--out", "frames", "--view", "diagonal"}),
            "stanceplan: --view: diagonal not in {front,side,top,three-quarter}");
  // A NaN camera would draw nothing: the command refuses it before reading the plan.
  const test::CliResult r = test::run_cli({"render", "plan.json", "--out",
                                           (test::temp_dir("cli_values") / "frames").string(),
                                           "--eye", "nan", "0", "0", "--target", "0", "0", "0"});
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_EQ(r.err, "stanceplan: error: --eye and --target: expected finite coordinates\n");
}

TEST(CliValues, ChoicesNameTheAllowedValues) {
  EXPECT_EQ(usage_error({"posture", kScenario, "--stance", "middle"}),
            "stanceplan: --stance: middle not in {initial,goal}");
  EXPECT_EQ(usage_error({"inspect", "m.urdf", "--kind", "flying"}),
            "stanceplan: --kind: flying not in {auto,fixed,floating,object,environment}");
  EXPECT_EQ(usage_error({"plan"}), "stanceplan: scenario is required");
}

TEST(CliValues, HelpDocumentsTheExitCodes) {
  const test::CliResult r = test::run_cli({"--help"});
  EXPECT_EQ(r.code, 0);
  EXPECT_THAT(
      r.out,
      HasSubstr("Exit codes: 0 success, 1 bad input or usage, 2 no plan found / check failed."));
  std::ifstream readme(test::source_path("README.md"));
  const std::string text((std::istreambuf_iterator<char>(readme)), {});
  EXPECT_THAT(text, HasSubstr("Exit codes: 0 success, 1 bad input or usage, 2 no plan found / no "
                              "posture / certification failed."));
}

}  // namespace
}  // namespace stanceplan
