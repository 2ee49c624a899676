// How events are named and described: file names, captions, the events.jsonl line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "app/live/event_record.h"
#include "tests/support/paths.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

using nlohmann::json;

class EventRecord : public ::testing::Test {
 protected:
  EventRecord() : scene_(test::humanoid_scene("flat_ground")) {
    Contact left{test::surface(scene_, "robot/l_sole"), test::surface(scene_, "env/floor")};
    Contact right{test::surface(scene_, "robot/r_sole"), test::surface(scene_, "env/floor")};
    candidate_.number = 12;
    candidate_.kind = SearchEventKind::Candidate;
    candidate_.node = -1;
    candidate_.parent = 3;
    candidate_.stance = Stance({left});
    candidate_.candidate_case = CandidateCase::Remove;
    candidate_.changed = right;
    candidate_.status = PostureStatus::Infeasible;
    candidate_.message = "equilibrium";
    candidate_.time_ms = 35.25;
    candidate_.milestone = 2;
    candidate_.nodes = 7;
  }
  Scene scene_;
  SearchEvent candidate_;
};

TEST_F(EventRecord, FileNamesSortInEventOrderAndNameTheKind) {
  EXPECT_EQ(app::snapshot_file_name(candidate_), "event_00012_candidate.png");
  SearchEvent found;
  found.number = 345;
  found.kind = SearchEventKind::PlanFound;
  EXPECT_EQ(app::snapshot_file_name(found), "event_00345_plan_found.png");
}

TEST_F(EventRecord, TheCaptionSaysWhatHappened) {
  EXPECT_EQ(app::event_caption(scene_, candidate_, 6),
            "Event 12 · candidate · remove r_sole from floor\n"
            "infeasible, rejected: equilibrium · 35.2 ms · target milestone 3 of 6\n"
            "stance: l_sole on floor");
  // Milestones counted from 1, as the panel's "aiming at milestone k of N".
  SearchEvent expansion = candidate_;
  expansion.kind = SearchEventKind::Expansion;
  expansion.node = 3;
  EXPECT_THAT(app::event_caption(scene_, expansion, 6),
              ::testing::HasSubstr("expanding node 3 · target milestone 3 of 6 · 7 nodes"));
}

TEST_F(EventRecord, TheJsonLineHoldsTheIndexFields) {
  const json j =
      json::parse(app::event_json_line(scene_, candidate_, 1.5, "event_00012_candidate.png"));
  EXPECT_EQ(j["number"], 12);
  EXPECT_EQ(j["kind"], "candidate");
  EXPECT_EQ(j["parent"], 3);
  EXPECT_EQ(j["stance"], json::parse(R"([["robot/l_sole", "env/floor"]])"));
  EXPECT_EQ(j["change"], "remove");
  EXPECT_EQ(j["changed"], json::parse(R"(["robot/r_sole", "env/floor"])"));
  EXPECT_EQ(j["status"], "infeasible");
  EXPECT_EQ(j["accepted"], false);
  EXPECT_EQ(j["message"], "equilibrium");
  EXPECT_DOUBLE_EQ(j["solve_ms"].get<double>(), 35.25);
  EXPECT_DOUBLE_EQ(j["time_s"].get<double>(), 1.5);
  EXPECT_EQ(j["image"], "event_00012_candidate.png");
  EXPECT_TRUE(json::parse(app::event_json_line(scene_, candidate_, 1.5, ""))["image"].is_null());
}

}  // namespace
}  // namespace stanceplan
