// FailureMemo: a failed candidate is recognised again in the same situation (same change, stance,
// posture and relation of its surfaces, wherever on the floor), and not in another.
#include "planner/search/failure_memo.h"

#include <gtest/gtest.h>

#include "planner/model/kinematics.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

TEST(FailureMemo, RecognisesTheSameSituationAnywhereOnTheFloorAndNothingElse) {
  const Scene scene = test::humanoid_scene("wall");
  const Eigen::VectorXd q = test::standing_configuration(scene);
  const Contact left = test::task(scene, "robot/l_sole", "env/floor").contact;
  const Contact right = test::task(scene, "robot/r_sole", "env/floor").contact;
  const Contact palm = test::task(scene, "robot/r_palm", "env/wall").contact;
  const Stance both({left, right});
  const Candidate palm_on_wall{true, palm};
  FailureMemo memo;
  const auto at = [&](const Eigen::VectorXd& config) {
    return system_kinematics(scene.system, config);
  };
  EXPECT_FALSE(memo.seen(scene, at(q), q, both, palm_on_wall));
  memo.record(scene, at(q), q, both, palm_on_wall);
  EXPECT_TRUE(memo.seen(scene, at(q), q, both, palm_on_wall));
  // The robot 2 cm to the side (along the wall): the palm stands as far from the wall.
  Eigen::VectorXd moved = q;
  moved[1] += 0.02;
  EXPECT_TRUE(memo.seen(scene, at(moved), moved, both, palm_on_wall));
  // 20 cm nearer the wall: another situation.
  Eigen::VectorXd nearer = q;
  nearer[0] += 0.2;
  EXPECT_FALSE(memo.seen(scene, at(nearer), nearer, both, palm_on_wall));
  // Another posture, another stance, another change: not seen.
  Eigen::VectorXd bent = q;
  bent[bent.size() - 1] += 0.5;
  EXPECT_FALSE(memo.seen(scene, at(bent), bent, both, palm_on_wall));
  EXPECT_FALSE(memo.seen(scene, at(q), q, Stance({left}), palm_on_wall));
  EXPECT_FALSE(memo.seen(scene, at(q), q, both, Candidate{false, palm}));
}

}  // namespace
}  // namespace stanceplan
