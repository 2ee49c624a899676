// `stanceplan plan --requests DIR` and `stanceplan replay`: every candidate's solver request is
// written under its event number, and replaying one alone gives the search's own result (status
// and Ipopt iterations: a solve is deterministic); a file that is not a request, is cut short, or
// does not fit the scenario is refused with the file named.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <regex>
#include <sstream>

#include "planner/io/request_file.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

struct CandidateLine {
  int event = 0;
  std::string status;
  bool accepted = false;
  int iterations = 0;
};

// The candidate lines of `plan --verbose`: "[N] candidate node ... add STATUS accepted (T ms, K
// iterations)" or "... rejected: why (T ms, K iterations)".
std::vector<CandidateLine> candidate_lines(const std::string& verbose) {
  static const std::regex line(
      R"(\[(\d+)\] candidate node -?\d+ \{.*\} (?:add|remove) (\S+) (accepted|rejected).*, (\d+) iterations\))");
  std::vector<CandidateLine> lines;
  std::istringstream in(verbose);
  for (std::string text; std::getline(in, text);) {
    std::smatch m;
    if (std::regex_search(text, m, line))
      lines.push_back({std::stoi(m[1]), m[2], m[3] == "accepted", std::stoi(m[4])});
  }
  return lines;
}

std::string request_file(const std::filesystem::path& dir, int event) {
  std::ostringstream name;
  name << "request_" << std::setw(5) << std::setfill('0') << event << ".bin";
  return (dir / name.str()).string();
}

TEST(ReplayCommand, ACandidateReplaysAloneToTheResultItHadInTheSearch) {
  const std::string scenario = test::source_path("scenarios/untuned/side_step.yaml");
  const std::filesystem::path dir = test::temp_dir("replay") / "requests";
  std::filesystem::remove_all(dir);
  const std::string plan = (test::temp_dir("replay") / "plan.json").string();
  const test::CliResult r = test::run_cli(
      {"plan", scenario, "--threads", "1", "--out", plan, "--requests", dir.string(), "--verbose"});
  ASSERT_EQ(r.code, 0) << r.err;
  const std::vector<CandidateLine> lines = candidate_lines(r.err);
  ASSERT_GT(lines.size(), 1u);
  // Each candidate line ends with the node it was tried from and the contact it adds or removes.
  static const std::regex change(
      R"(candidate node -?\d+ \{.*\} (add|remove) .* · from node \d+: \1 \S+ (on|from) \S+$)");
  size_t named = 0;
  std::istringstream err(r.err);
  for (std::string text; std::getline(err, text);) named += std::regex_search(text, change);
  EXPECT_EQ(named, lines.size()) << r.err;
  // One file per candidate that adds or removes a contact (the root, realised before the search
  // and listed without either, has none).
  size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    files += entry.is_regular_file();
  EXPECT_EQ(files, lines.size());
  bool replayed_rejected = false, replayed_accepted = false;
  for (const CandidateLine& c : lines) {
    if (c.accepted ? replayed_accepted : replayed_rejected) continue;
    ASSERT_TRUE(std::filesystem::exists(request_file(dir, c.event))) << c.event;
    const test::CliResult replay = test::run_cli({"replay", scenario, request_file(dir, c.event)});
    EXPECT_EQ(replay.code, c.status == "solved" ? 0 : 2) << replay.out << replay.err;
    EXPECT_THAT(replay.out, HasSubstr(": " + c.status + " after " + std::to_string(c.iterations) +
                                      " Ipopt iterations"))
        << "event " << c.event;
    (c.accepted ? replayed_accepted : replayed_rejected) = true;
  }
  EXPECT_TRUE(replayed_accepted);
  EXPECT_TRUE(replayed_rejected);
  // Another iteration limit: the same request stops there.
  const CandidateLine& first = lines.front();
  const test::CliResult short_run =
      test::run_cli({"replay", scenario, request_file(dir, first.event), "--max-iterations", "1"});
  EXPECT_THAT(short_run.out, HasSubstr("after 1 Ipopt iterations"));
  // A candidate the progress budget stopped (the side-step's knees on the floor): without the
  // budget it runs to the solver's iteration limit (100), its log then Ipopt's own end.
  const auto stalled = std::find_if(lines.begin(), lines.end(), [](const CandidateLine& c) {
    return c.status == "iteration_limit" && c.iterations < 100;
  });
  ASSERT_NE(stalled, lines.end()) << r.err;
  const std::string request = request_file(dir, stalled->event);
  EXPECT_THAT(test::run_cli({"replay", scenario, request}).out, HasSubstr("Stalled (no progress"));
  const test::CliResult unbudgeted =
      test::run_cli({"replay", scenario, request, "--progress-budget", "0"});
  EXPECT_EQ(unbudgeted.code, 2);
  EXPECT_THAT(unbudgeted.out, HasSubstr("after 100 Ipopt iterations"));
  EXPECT_THAT(unbudgeted.out, HasSubstr("Maximum_Iterations_Exceeded"));
  // What the solver was asked: the kept contact at its placement, the new one with its E25 target
  // (free, or first tried at the goal's stated placement: the side-step's last step).
  const test::CliResult shown = test::run_cli({"replay", scenario, request, "--show-request"});
  EXPECT_THAT(shown.out,
              ::testing::ContainsRegex(
                  R"(contact robot/._sole on env/floor: loaded placed at \(-?[0-9.]+, )"));
  EXPECT_THAT(
      shown.out,
      ::testing::ContainsRegex(
          R"(contact robot/\S+ on env/floor: unloaded (free|placed at \([^)]*\)) target \()"));
}

TEST(ReplayCommand, FilesThatAreNotRequestsOfThisScenarioAreRefusedWithTheFileNamed) {
  const std::string scenario = test::source_path("scenarios/untuned/side_step.yaml");
  const std::filesystem::path dir = test::temp_dir("replay_faults");
  const std::string missing = (dir / "missing.bin").string();
  std::filesystem::remove(missing);
  test::CliResult r = test::run_cli({"replay", scenario, missing});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "stanceplan: error: " + missing + ": no such file\n");

  const std::string text = (dir / "text.bin").string();
  std::ofstream(text) << "hello\nworld\n";
  r = test::run_cli({"replay", scenario, text});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "stanceplan: error: " + text +
                       ": expected a solver request (first line \"stanceplan/request@1\", written "
                       "by stanceplan plan --requests), found \"hello\"\n");

  const std::string cut = (dir / "cut.bin").string();
  std::ofstream(cut) << kRequestFileHeader << "abc";
  r = test::run_cli({"replay", scenario, cut});
  EXPECT_EQ(r.code, 1);
  EXPECT_EQ(r.err, "stanceplan: error: " + cut +
                       ": a solver request cut short or written by another build (solver pool: "
                       "truncated message)\n");

  // A request for another system (39 coordinates) replayed on the two arms and the cylinder.
  PostureRequest humanoid;
  humanoid.q_init = Eigen::VectorXd::Zero(39);
  const std::string other = (dir / "other.bin").string();
  write_request_file(other, humanoid);
  const std::string arms = test::source_path("scenarios/dual_arm_cylinder.yaml");
  r = test::run_cli({"replay", arms, other});
  EXPECT_EQ(r.code, 1);
  EXPECT_THAT(r.err, HasSubstr("stanceplan: error: " + other + ": does not fit " + arms +
                               ": q_init has 39 entries, the system has "));
}

}  // namespace
}  // namespace stanceplan
