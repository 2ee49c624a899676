// `stanceplan inspect` on the real robots, its JSON fields, and its exit codes on bad input.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <nlohmann/json.hpp>
#include <sstream>

#include "app/cli.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

using test::CliResult;
CliResult run(std::vector<std::string> args) {
  return test::run_cli(std::move(args));
}

TEST(Inspect, TalosJson) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const CliResult r = run({"inspect", test::talos_urdf(), "--package-path",
                           test::talos_package_dir(), "--kind", "floating", "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out);
  EXPECT_EQ(d["name"], "talos");
  EXPECT_EQ(d["dof"], 32);
  EXPECT_NEAR(d["mass"].get<double>(), 90.2722, 1e-3);
  EXPECT_EQ(d["floating"], true);
  ASSERT_EQ(d["joints"].size(), 32u);
  for (const auto& j : d["joints"]) {
    for (const char* key : {"name", "type", "lower", "upper", "effort"})
      EXPECT_TRUE(j.contains(key)) << key;
    EXPECT_GT(j["effort"].get<double>(), 0.0) << j["name"];
  }
  EXPECT_EQ(d["links"].size(), 60u);
  EXPECT_TRUE(d["surfaces"].empty());
}

TEST(Inspect, TalosCollisionObjectsAreBuiltAndTheSrdfDisablesPairs) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const std::string srdf = test::shared_path("robots/talos/robots/talos_data/srdf/talos.srdf");
  const CliResult with =
      run({"inspect", test::talos_urdf(), "--package-path", test::talos_package_dir(), "--kind",
           "floating", "--srdf", srdf, "--json"});
  const CliResult without = run({"inspect", test::talos_urdf(), "--package-path",
                                 test::talos_package_dir(), "--kind", "floating", "--json"});
  ASSERT_EQ(with.code, 0) << with.err;
  ASSERT_EQ(without.code, 0) << without.err;
  const auto a = nlohmann::json::parse(with.out)["collision"],
             b = nlohmann::json::parse(without.out)["collision"];
  EXPECT_GT(a["mesh_hulls"].get<int>(), 30);
  EXPECT_GT(a["srdf_disabled_pairs"].get<int>(), 0);
  EXPECT_LT(a["candidate_pairs"].get<int>(), b["candidate_pairs"].get<int>());
  EXPECT_EQ(b["srdf_disabled_pairs"], 0);
}

TEST(Inspect, PandaJsonListsPrismaticAndMimicJoints) {
  STANCEPLAN_REQUIRE_SHARED("robots/panda");
  const CliResult r =
      run({"inspect", test::panda_urdf(), "--package-path", test::panda_package_dir(), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out);
  EXPECT_EQ(d["dof"], 8);
  EXPECT_EQ(d["floating"], false);
  EXPECT_EQ(d["kind"], "fixed");
  const auto& joints = d["joints"];
  ASSERT_EQ(joints.size(), 9u);
  EXPECT_EQ(joints[8]["type"], "prismatic");
  EXPECT_EQ(joints[8]["mimic"]["joint"], "panda_finger_joint1");
}

TEST(Inspect, TextOutputSummarisesTheModel) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const CliResult r =
      run({"inspect", test::talos_urdf(), "--package-path", test::talos_package_dir()});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("actuated dofs: 32   mass: 90.2722 kg   links: 60"));
  EXPECT_THAT(r.out, HasSubstr("leg_left_4_joint"));
}

TEST(Inspect, MissingFileExitsOneWithTheFileNamed) {
  const CliResult r = run({"inspect", "/nonexistent/robot.urdf"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "stanceplan: error: /nonexistent/robot.urdf: no such file\n");
}

TEST(Inspect, UsageErrorsExitOne) {
  EXPECT_EQ(run({"--no-such-option"}).code, 1);  // (no argument at all is the main job)
  EXPECT_EQ(run({"inspect"}).code, 1);
  const CliResult r = run({"inspect", test::panda_urdf(), "--kind", "wheeled"});
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("--kind"));
}

TEST(Inspect, BinaryExitCodes) {
  const std::string bin = STANCEPLAN_BINARY;
  EXPECT_EQ(std::system((bin + " --help > /dev/null").c_str()), 0);
  const int status = std::system((bin + " inspect /nonexistent.urdf 2> /dev/null").c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
}

}  // namespace
}  // namespace stanceplan
