// The hot path around FCL allocates nothing: shape pose updates, gradients (dense and sparse),
// gradient blocks and the bounding-sphere bound. Counts every heap allocation (malloc, which both
// operator new and Eigen use), see tests/support/allocation_counter.h.
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "tests/planner/collision/collision_test_scene.h"
#include "tests/support/allocation_counter.h"

namespace stanceplan {
namespace {

TEST(SignedDistance, PoseUpdateAndGradientsDoNotAllocate) {
  if (!test::kCountsAllocations) GTEST_SKIP() << "malloc belongs to the sanitizer in this build";
  test::Scene s;
  const Eigen::VectorXd q = s.generic_configuration();
  s.set(q);
  const int pair = s.pair(s.arm, "finger", s.body, "limb");
  ASSERT_GE(pair, 0);
  const DistanceResult r = signed_distance(*s.model, *s.work, pair);
  const GradientBlocks blocks = gradient_blocks(s.system, *s.model, pair);
  Eigen::RowVectorXd dense(s.system.nq());
  Eigen::RowVectorXd sparse(blocks.total_size());

  const long before = test::allocations();
  for (int e = 0; e < s.system.num_entities(); ++e) {
    forward_kinematics(s.system.entity(e), q.segment(s.system.offset(e), s.system.entity(e).nq()),
                       s.data[e]);
  }
  s.work->update(*s.model, s.data);
  signed_distance_gradient(s.system, s.data, *s.model, pair, r, *s.work, dense);
  signed_distance_gradient_sparse(s.system, s.data, *s.model, pair, r, *s.work, sparse);
  const GradientBlocks again = gradient_blocks(s.system, *s.model, pair);
  const double bound = distance_lower_bound(*s.model, s.data, pair);
  EXPECT_EQ(test::allocations() - before, 0);
  EXPECT_EQ(again.count, blocks.count);
  EXPECT_LE(bound, r.distance);
  // The counter is live: FCL itself allocates its GJK shape objects on every query.
  const long fcl_before = test::allocations();
  signed_distance(*s.model, *s.work, pair);
  EXPECT_GT(test::allocations() - fcl_before, 0);
}

}  // namespace
}  // namespace stanceplan
