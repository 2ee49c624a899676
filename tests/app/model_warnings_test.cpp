// Ignored inertia tensors (planner/model/ignored_inertia.h) on the command line: `inspect` lists
// them and exits 0; a command that loads a scenario prints one warning line per URDF file, however
// many entities load it; the real robots of ../shared load and inspect.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

std::string cad_arm() {
  return test::source_path("tests/data/inertia_faults/cad_arm.urdf");
}

std::string cad_arm_warning() {
  return cad_arm() +
         ": inertia of 2 links ignored (not used by the statics): upper (triangle inequality "
         "broken: principal moments 0.125 0.125 0.5, 0.5 > 0.25), forearm (not positive "
         "semi-definite: principal moments -0.03125 0.0625 0.0625)";
}

size_t count(const std::string& text, const std::string& part) {
  size_t n = 0;
  for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
  return n;
}

TEST(ModelWarnings, InspectListsTheIgnoredTensors) {
  const test::CliResult text = test::run_cli({"inspect", cad_arm()});
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_THAT(text.out, HasSubstr("warning: " + cad_arm_warning() + "\n"));
  const test::CliResult json = test::run_cli({"inspect", cad_arm(), "--json"});
  ASSERT_EQ(json.code, 0) << json.err;
  const auto d = nlohmann::json::parse(json.out);
  ASSERT_EQ(d["ignored_inertias"].size(), 2u);
  EXPECT_EQ(d["ignored_inertias"][0]["link"], "upper");
  EXPECT_EQ(d["ignored_inertias"][1]["link"], "forearm");
  EXPECT_EQ(d["warnings"], nlohmann::json::array({cad_arm_warning()}));
  EXPECT_EQ(json.err, "warning: " + cad_arm_warning() + "\n");
}

// The humanoid stands on the floor beside two copies of the arm (fixed robots).
TEST(ModelWarnings, AScenarioCommandPrintsOneLinePerFile) {
  const std::string assets = test::source_path("assets");
  const std::string env = assets + "/environments/flat_ground/flat_ground";
  const std::string path = (test::temp_dir("model_warnings") / "arms.yaml").string();
  std::string arms;
  for (const char* name : {"arm1", "arm2"})
    arms += std::string("  - name: ") + name + "\n    kind: fixed\n    urdf: " + cad_arm() +
            "\n    base_pose: {position: [" + (name[3] == '1' ? "2" : "-2") + ", 0, 0]}\n";
  std::ofstream(path) << "format: stanceplan/scenario@1\n"
                         "entities:\n"
                         "  - name: robot\n"
                         "    kind: floating\n"
                         "    urdf: " +
                             assets + "/robots/humanoid/humanoid.urdf\n    surfaces: " + assets +
                             "/robots/humanoid/humanoid.surfaces.yaml\n"
                             "    configuration: {base_position: [0, 0, 0.9]}\n" +
                             arms + "  - name: env\n    kind: environment\n    urdf: " + env +
                             ".urdf\n    surfaces: " + env +
                             ".surfaces.yaml\n"
                             "stances:\n"
                             "  initial: [{s1: robot/l_sole, s2: env/floor}, {s1: robot/r_sole, "
                             "s2: env/floor}]\n"
                             "  goal: [{s1: robot/l_sole, s2: env/floor}, {s1: robot/r_sole, s2: "
                             "env/floor}]\n";
  const test::CliResult r = test::run_cli({"posture", path});
  EXPECT_EQ(count(r.err, "stanceplan: warning: " + cad_arm_warning() + "\n"), 1u) << r.err;
  EXPECT_EQ(count(r.err, "inertia of"), 1u) << r.err;
}

TEST(ModelWarnings, ThePandaLoadsAndInspects) {
  STANCEPLAN_REQUIRE_SHARED("robots/panda");
  const test::CliResult r = test::run_cli(
      {"inspect", test::panda_urdf(), "--package-path", test::panda_package_dir(), "--srdf",
       test::shared_path("robots/panda/robots/panda_description/srdf/panda.srdf"), "--json"});
  ASSERT_EQ(r.code, 0) << r.err;
  const auto d = nlohmann::json::parse(r.out);
  EXPECT_EQ(d["dof"], 8);
  // Its published tensors are all ones a body can have (within the loader's 2 % rounding).
  EXPECT_TRUE(d["ignored_inertias"].empty()) << d["ignored_inertias"].dump();
}

}  // namespace
}  // namespace stanceplan
