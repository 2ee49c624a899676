// `stanceplan panel`: its usage errors and what it says when no window can be opened, in-process
// (the window itself is tested under Xvfb in panel_window_test.cpp).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>

#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

TEST(PanelCommand, WithoutADisplayItSaysSoAndExitsOne) {
  unsetenv("DISPLAY");  // this test process only
  unsetenv("WAYLAND_DISPLAY");
  const test::CliResult r =
      test::run_cli({"panel", test::source_path("scenarios/humanoid_walk.yaml")});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err,
            "stanceplan: error: cannot open a window: X11: The DISPLAY environment variable is "
            "missing (GLFW error 65544)\n");
}

TEST(PanelCommand, AWindowSizeOutOfRangeIsAUsageError) {
  const test::CliResult r = test::run_cli(
      {"panel", test::source_path("scenarios/humanoid_walk.yaml"), "--size", "10x10"});
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("--size: expected WIDTHxHEIGHT between 640x400 and 7680x4320, "
                               "found \"10x10\""));
}

TEST(PanelCommand, AMissingScenarioIsNamedBeforeAnyWindowOpens) {
  unsetenv("DISPLAY");
  const std::string missing = test::temp_dir("panel_missing").string() + "/none.yaml";
  const test::CliResult r = test::run_cli({"panel", missing});
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr(missing));
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("window")));
}

}  // namespace
}  // namespace stanceplan
