// Plans with point contacts through their files: `stanceplan posture` on the round-fingertip hand
// holding the ball writes each tip as a point surface and its force at the contact point, which
// `stanceplan certify` accepts; a finger bent so that its tip leaves the ball's face fails
// "contact plane", naming the tip and the face.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using nlohmann::json;
using ::testing::HasSubstr;

class CertifyPointContacts : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    path_ = new std::string((test::temp_dir("certify_point") / "ball_point.json").string());
    const test::CliResult r = test::run_cli(
        {"posture", test::source_path("scenarios/hand_ball_rotate_point.yaml"), "--out", *path_});
    ASSERT_EQ(r.code, 0) << r.err;
    std::ifstream in(*path_);
    plan_ = new json(json::parse(in));
  }
  static void TearDownTestSuite() {
    delete plan_;
    delete path_;
  }
  static std::string* path_;
  static json* plan_;
};
std::string* CertifyPointContacts::path_ = nullptr;
json* CertifyPointContacts::plan_ = nullptr;

TEST_F(CertifyPointContacts, TheTipsAreWrittenAsPointsAndCertified) {
  int points = 0;
  for (const json& s : (*plan_)["surfaces"])
    if (s.value("kind", "") == "point") {
      ++points;
      EXPECT_EQ(s["radius"], 0.007);
      EXPECT_FALSE(s.contains("vertices"));
    }
  EXPECT_EQ(points, 4);
  EXPECT_EQ((*plan_)["steps"][0]["forces"].size(), 4u);  // one force per fingertip
  const test::CliResult r = test::run_cli({"certify", *path_});
  EXPECT_EQ(r.code, 0) << r.out << r.err;
  EXPECT_THAT(r.out, HasSubstr("all checks passed"));
}

TEST_F(CertifyPointContacts, ATipMovedOffTheFaceFailsContactPlane) {
  json copy = *plan_;
  json& joints = copy["steps"][0]["configuration"]["hand"]["joints"];
  joints["fl_base_pitch"] = joints["fl_base_pitch"].get<double>() - 0.1;  // the finger opens
  const std::string path = (test::temp_dir("certify_point") / "tip_off.json").string();
  std::ofstream(path) << copy.dump();
  const test::CliResult r = test::run_cli({"certify", path});
  EXPECT_EQ(r.code, 2);
  EXPECT_THAT(r.err, HasSubstr("certification failed: contact plane at step 0: hand/fl_tip on "
                               "ball/s5, the centre not one radius from the plane"));
}

}  // namespace
}  // namespace stanceplan
