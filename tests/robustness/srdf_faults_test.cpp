// SRDF faults reached through a scenario: a malformed or truncated SRDF, a <disable_collisions>
// without its links, a file that is not an SRDF and a missing file each make `stanceplan posture`
// exit 1 with the SRDF file, its line and the fault named.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

// The humanoid on flat ground with `srdf` as the robot's SRDF.
std::string scenario_with_srdf(const std::string& name, const std::string& srdf) {
  const std::string assets = test::source_path("assets");
  const std::string path = (test::temp_dir("srdf_faults") / (name + ".yaml")).string();
  std::ofstream(path)
      << "format: stanceplan/scenario@1\n"
         "entities:\n"
         "  - name: robot\n"
         "    kind: floating\n"
         "    urdf: "
      << assets
      << "/robots/humanoid/humanoid.urdf\n"
         "    surfaces: "
      << assets
      << "/robots/humanoid/humanoid.surfaces.yaml\n"
         "    srdf: "
      << srdf
      << "\n"
         "    configuration: {base_position: [0, 0, 0.9]}\n"
         "  - name: env\n"
         "    kind: environment\n"
         "    urdf: "
      << assets
      << "/environments/flat_ground/flat_ground.urdf\n"
         "    surfaces: "
      << assets
      << "/environments/flat_ground/flat_ground.surfaces.yaml\n"
         "stances:\n"
         "  initial: [{s1: robot/l_sole, s2: env/floor}, {s1: robot/r_sole, s2: env/floor}]\n"
         "  goal: [{s1: robot/l_sole, s2: env/floor}, {s1: robot/r_sole, s2: env/floor}]\n";
  return path;
}

std::string srdf_file(const std::string& name, const std::string& text) {
  const std::string path = (test::temp_dir("srdf_faults") / name).string();
  std::ofstream(path) << text;
  return path;
}

// The error line of `stanceplan posture` on a scenario naming `srdf`.
std::string posture_error(const std::string& name, const std::string& srdf) {
  const test::CliResult r = test::run_cli({"posture", scenario_with_srdf(name, srdf)});
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  return r.err;
}

TEST(SrdfFaults, AMalformedOrTruncatedSrdfNamesFileAndLine) {
  const std::string truncated =
      srdf_file("truncated.srdf",
                "<robot name=\"humanoid\">\n"
                "  <disable_collisions link1=\"l_foot\" link2=\"r_foot\" reason=\"Never\"/>\n"
                "  <disable_collisions link1=\"l_foot\"");
  EXPECT_THAT(posture_error("truncated", truncated),
              HasSubstr("stanceplan: error: " + truncated + ":3: malformed XML: "));
}

TEST(SrdfFaults, ADisabledPairWithoutItsLinksNamesFileAndLine) {
  const std::string missing =
      srdf_file("missing_link2.srdf",
                "<robot name=\"humanoid\">\n"
                "  <disable_collisions link1=\"l_foot\" link2=\"r_foot\"/>\n"
                "  <disable_collisions link1=\"l_foot\" reason=\"Never\"/>\n"
                "</robot>\n");
  EXPECT_EQ(posture_error("missing_link2", missing),
            "stanceplan: error: " + missing +
                ":3: <disable_collisions>: expected attributes link1 and link2\n");
}

TEST(SrdfFaults, NotAnSrdfAndAMissingFileAreNamed) {
  const std::string not_srdf =
      srdf_file("not_srdf.srdf", "<?xml version=\"1.0\"?>\n<model name=\"x\"/>\n");
  EXPECT_EQ(
      posture_error("not_srdf", not_srdf),
      "stanceplan: error: " + not_srdf + ": not an SRDF file: the root element must be <robot>\n");
  const std::string absent = (test::temp_dir("srdf_faults") / "absent.srdf").string();
  EXPECT_EQ(posture_error("absent", absent), "stanceplan: error: " + absent + ": no such file\n");
  const std::string empty = srdf_file("empty.srdf", "");
  EXPECT_THAT(posture_error("empty", empty), HasSubstr("stanceplan: error: " + empty + ":"));
}

}  // namespace
}  // namespace stanceplan
