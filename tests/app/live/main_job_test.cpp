// The main job (`stanceplan [SCENARIO.yaml]`, no sub-command): headless output folder, the
// default scenario's lookup from the executable, the fallback when the panel is not built.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <stdlib.h>

#include <fstream>

#include "app/live/data_dir.h"
#include "app/live/main_job.h"
#include "tests/app/live/live_fixtures.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

TEST(MainJob, HeadlessWritesEverythingIntoTheOutputFolder) {
  const fs::path out = test::temp_dir("main_job") / "stanceplan-out";
  const test::CliResult r = test::run_cli({test::source_path("scenarios/humanoid_walk.yaml"),
                                           "--headless", "--out", out.string(), "--threads", "1"});
  ASSERT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("everything goes to " + out.string()));
  EXPECT_THAT(r.out, HasSubstr("all checks passed"));
  EXPECT_THAT(r.out, HasSubstr("main job done, in " + out.string()));
  EXPECT_THAT(r.out, HasSubstr("motion: 22 steps, "));  // on by default (--no-motion: off)
  for (const char* file :
       {"plan.json", "events.jsonl", "strip.png", "sequence.gif", "steps/step_000.png"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  const auto events = test::read_jsonl(out / "events.jsonl");
  ASSERT_FALSE(events.empty());
  EXPECT_EQ(events.back()["kind"], "plan_found");
  EXPECT_EQ(test::count_pngs(out, "event_"), static_cast<int>(events.size()));
  EXPECT_TRUE(test::has_png_signature(test::read_bytes(out / "strip.png")));
}

TEST(MainJob, AMissingScenarioIsBadInput) {
  const fs::path out = test::temp_dir("main_job_missing") / "out";
  const test::CliResult r =
      test::run_cli({"/nonexistent/scenario.yaml", "--headless", "--out", out.string()});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "stanceplan: error: /nonexistent/scenario.yaml: no such file\n");
  EXPECT_FALSE(fs::exists(out)) << "nothing is written for bad input";
}

TEST(MainJob, TheDefaultScenarioIsFoundFromTheBuildWhateverTheCurrentFolder) {
  const fs::path before = fs::current_path();
  fs::current_path(test::temp_dir("main_job_cwd"));
  const std::string path = app::default_scenario_path();
  fs::current_path(before);
  EXPECT_EQ(path, test::source_path(app::kDefaultScenario));
  EXPECT_TRUE(fs::exists(path));
}

TEST(MainJob, AnInstalledExecutableReadsItsShareFolder) {
  const fs::path prefix = test::temp_dir("main_job_prefix");
  fs::create_directories(prefix / "bin");
  fs::create_directories(prefix / "share/stanceplan/scenarios");
  EXPECT_EQ(app::find_data_dir(prefix / "bin/stanceplan"), prefix / "share/stanceplan");
  // Not installed: the source tree of the build.
  EXPECT_EQ(app::find_data_dir("/nonexistent/bin/stanceplan"), fs::path(STANCEPLAN_SOURCE_DIR));
}

}  // namespace
}  // namespace stanceplan
