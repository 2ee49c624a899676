// `stanceplan plan --snapshots DIR`: one image per event listed in events.jsonl, every image a
// valid PNG, contiguous numbering, the right kinds, and the final steps and strip.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include "app/live/event_record.h"
#include "tests/app/live/live_fixtures.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

std::string expected_name(int number, const std::string& kind) {
  char name[64];
  std::snprintf(name, sizeof(name), "event_%05d_%s.png", number, kind.c_str());
  return name;
}

TEST(Snapshots, EveryListedEventOfTheWalkHasItsPngAndTheSequenceIsDrawn) {
  const auto dir = test::temp_dir("snapshots_walk");
  const std::string plan = (dir / "plan.json").string(), snaps = (dir / "snaps").string();
  const test::CliResult r =
      test::run_cli({"plan", test::source_path("scenarios/humanoid_walk.yaml"), "--out", plan,
                     "--snapshots", snaps, "--threads", "1"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<json> events = test::read_jsonl(std::filesystem::path(snaps) / "events.jsonl");
  ASSERT_GT(events.size(), 10u);
  EXPECT_THAT(r.out, HasSubstr("snapshots: " + std::to_string(events.size()) + " images of " +
                               std::to_string(events.size()) + " search events in " + snaps));

  std::map<std::string, int> kinds;
  for (size_t i = 0; i < events.size(); ++i) {
    const json& e = events[i];
    ASSERT_EQ(e["number"].get<int>(), static_cast<int>(i)) << "numbering is contiguous";
    const std::string kind = e["kind"];
    ++kinds[kind];
    ASSERT_EQ(e["image"], expected_name(int(i), kind));
    const auto file = std::filesystem::path(snaps) / e["image"].get<std::string>();
    const std::string bytes = test::read_bytes(file);
    ASSERT_TRUE(test::has_png_signature(bytes)) << file;
    const render::Image image = render::decode_png(bytes, file.string());
    EXPECT_EQ(image.width, 960);
    EXPECT_EQ(image.height, 540);
    if (kind == "candidate") {
      EXPECT_TRUE(e.contains("status") && e.contains("accepted") && e.contains("solve_ms"))
          << e.dump();
      if (!e["accepted"].get<bool>()) {
        EXPECT_TRUE(e.contains("message")) << e.dump();
      }
    }
    EXPECT_GE(e["time_s"].get<double>(), i ? events[i - 1]["time_s"].get<double>() : 0.0);
  }
  EXPECT_EQ(test::count_pngs(snaps, "event_"), static_cast<int>(events.size()))
      << "no image beyond the listed ones";
  // One framing for the whole search: the root and the goal differ where the robot walked 1.5 m.
  const render::Image first = render::read_png(
      (std::filesystem::path(snaps) / events.front()["image"].get<std::string>()).string());
  const render::Image last = render::read_png(
      (std::filesystem::path(snaps) / events.back()["image"].get<std::string>()).string());
  ASSERT_EQ(first.rgba.size(), last.rgba.size());
  size_t changed = 0;
  for (size_t p = 0; p < first.rgba.size(); p += 4)
    changed += std::abs(int(first.rgba[p]) - int(last.rgba[p])) +
                   std::abs(int(first.rgba[p + 1]) - int(last.rgba[p + 1])) >
               40;
  EXPECT_GT(changed, first.rgba.size() / 4 / 100)
      << "more than 1 % of the pixels change between root and goal";
  // The root is the first (accepted) candidate; expansions follow; the walk reaches its 6
  // milestones and the goal, which is the last event.
  EXPECT_EQ(events.front()["kind"], "candidate");
  EXPECT_EQ(events.front()["accepted"], true);
  EXPECT_EQ(events.back()["kind"], "plan_found");
  EXPECT_EQ(kinds["plan_found"], 1);
  EXPECT_EQ(kinds["failure"], 0);
  EXPECT_GT(kinds["expansion"], 0);
  EXPECT_GT(kinds["milestone"], 0);
  EXPECT_EQ(kinds["expansion"] + kinds["candidate"] + kinds["milestone"] + kinds["plan_found"],
            static_cast<int>(events.size()));

  // The final sequence: one step image per plan step and the strip, all valid PNGs.
  std::ifstream plan_in(plan);
  const json plan_json = json::parse(plan_in);
  const size_t steps = plan_json["steps"].size();
  EXPECT_EQ(test::count_pngs(std::filesystem::path(snaps) / "steps", "step_"),
            static_cast<int>(steps));
  const std::string strip = test::read_bytes(std::filesystem::path(snaps) / "strip.png");
  ASSERT_TRUE(test::has_png_signature(strip));
  EXPECT_GT(render::decode_png(strip, "strip.png").width, 960);
}

TEST(Snapshots, RejectedCandidatesCanBeListedWithoutImages) {
  const auto dir = test::temp_dir("snapshots_no_rejected");
  const std::string snaps = (dir / "snaps").string();
  // A stale image from an earlier run is removed, so that the folder holds only this run's.
  std::filesystem::create_directories(snaps);
  std::ofstream(std::filesystem::path(snaps) / "event_99999_candidate.png") << "stale";
  const test::CliResult r =
      test::run_cli({"plan", test::source_path("scenarios/dual_arm_cylinder.yaml"), "--out",
                     (dir / "plan.json").string(), "--snapshots", snaps, "--no-rejected-snapshots",
                     "--threads", "1", "--time-limit", "900"});  // sanitizers on a loaded machine:
  ASSERT_EQ(r.code, 0) << r.err;  // 58.8 s (TSan) and 63 s (ASan) of the file's 60 s were seen
  int rejected = 0, images = 0;
  for (const json& e : test::read_jsonl(std::filesystem::path(snaps) / "events.jsonl")) {
    const bool is_rejected = e["kind"] == "candidate" && !e["accepted"].get<bool>();
    rejected += is_rejected;
    if (is_rejected) {
      EXPECT_TRUE(e["image"].is_null()) << e.dump();
    } else {
      ASSERT_TRUE(e["image"].is_string()) << e.dump();
      EXPECT_TRUE(
          std::filesystem::exists(std::filesystem::path(snaps) / e["image"].get<std::string>()));
      ++images;
    }
  }
  EXPECT_GT(rejected, 0) << "the hand-over rejects candidates (the walk and the climb reject none)";
  EXPECT_EQ(test::count_pngs(snaps, "event_"), images);
}

TEST(Snapshots, AFolderThatCannotBeMadeIsBadInput) {
  const auto dir = test::temp_dir("snapshots_bad_dir");
  const std::string file = (dir / "a_file").string();
  std::ofstream(file) << "not a folder";
  const test::CliResult r =
      test::run_cli({"plan", test::source_path("scenarios/humanoid_walk.yaml"), "--out",
                     (dir / "plan.json").string(), "--snapshots", file + "/snaps"});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "stanceplan: error: " + file +
                       "/snaps: cannot prepare the snapshot folder (Not a directory)\n");
  EXPECT_FALSE(std::filesystem::exists(dir / "plan.json"));
}

}  // namespace
}  // namespace stanceplan
