// The guide path (guide_path.h): distances over the entries a milestone states, the guide's
// posture near a node, and which milestones state the same entries (the search lets a node pass a
// milestone only towards one of the same kind: StanceSearch::Run::reaches_milestone).
#include <gtest/gtest.h>

#include "planner/search/guide_path.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

// A mask stating the humanoid's base position only (a coarse guide's milestone).
Eigen::VectorXd base_position_mask(Eigen::Index size) {
  Eigen::VectorXd mask = Eigen::VectorXd::Zero(size);
  mask.head<3>().setOnes();
  return mask;
}

TEST(GuidePath, ABasePositionMilestoneMeasuresTheBaseOnly) {
  const Scene scene = test::humanoid_scene("flat_ground");
  const Eigen::VectorXd standing = test::standing_configuration(scene);
  Eigen::VectorXd milestone = standing;
  milestone[0] += 0.3;
  const GuidePath guide(scene.system, {milestone}, {base_position_mask(standing.size())});
  Eigen::VectorXd bent = standing;
  bent.tail(3).array() += 0.5;  // joints the milestone does not state
  EXPECT_NEAR(guide.distance_to(standing, 0), 0.3, 1e-12);
  EXPECT_NEAR(guide.distance_to(bent, 0), 0.3, 1e-12);
  // The guide's posture near a node: the node's joints at the milestone's base.
  const Eigen::VectorXd near = guide.posture_near(bent, 0);
  EXPECT_DOUBLE_EQ(near[0], milestone[0]);
  EXPECT_TRUE(near.tail(3).isApprox(bent.tail(3)));
}

TEST(GuidePath, MilestonesOfOneKindStateTheSameEntries) {
  const Scene scene = test::humanoid_scene("flat_ground");
  const Eigen::VectorXd q = test::standing_configuration(scene);
  const Eigen::VectorXd position = base_position_mask(q.size());
  Eigen::VectorXd heading = position;
  heading.segment<4>(3).setOnes();  // the base's orientation too
  const Eigen::VectorXd whole = Eigen::VectorXd::Ones(q.size());
  const GuidePath guide(scene.system, {q, q, q, q}, {position, position, heading, whole});
  EXPECT_TRUE(guide.same_entries(0, 1));
  EXPECT_FALSE(guide.same_entries(1, 2));
  EXPECT_FALSE(guide.same_entries(2, 3));
  // Without masks every milestone states every entry.
  const GuidePath unmasked(scene.system, {q, q});
  EXPECT_TRUE(unmasked.same_entries(0, 1));
  EXPECT_TRUE(GuidePath(scene.system, {q, q}, {whole}).same_entries(0, 1));
  EXPECT_FALSE(GuidePath(scene.system, {q, q}, {position}).same_entries(0, 1));
}

}  // namespace
}  // namespace stanceplan
