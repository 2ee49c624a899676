// The hot path around FCL allocates nothing: shape pose updates, gradients (dense and sparse),
// gradient blocks and the bounding-sphere bound. Counts calls to the global operator new, which
// this file replaces for the whole test executable (counting only).
#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <new>

#include "tests/planner/collision/collision_test_scene.h"

namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t size) {
  ++g_allocations;
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace stanceplan {
namespace {

TEST(SignedDistance, PoseUpdateAndGradientsDoNotAllocate) {
  test::Scene s;
  const Eigen::VectorXd q = s.generic_configuration();
  s.set(q);
  const int pair = s.pair(s.arm, "finger", s.body, "limb");
  ASSERT_GE(pair, 0);
  const DistanceResult r = signed_distance(*s.model, *s.work, pair);
  const GradientBlocks blocks = gradient_blocks(s.system, *s.model, pair);
  Eigen::RowVectorXd dense(s.system.nq());
  Eigen::RowVectorXd sparse(blocks.total_size());

  const long before = g_allocations.load();
  for (int e = 0; e < s.system.num_entities(); ++e) {
    forward_kinematics(s.system.entity(e), q.segment(s.system.offset(e), s.system.entity(e).nq()),
                       s.data[e]);
  }
  s.work->update(*s.model, s.data);
  signed_distance_gradient(s.system, s.data, *s.model, pair, r, *s.work, dense);
  signed_distance_gradient_sparse(s.system, s.data, *s.model, pair, r, *s.work, sparse);
  const GradientBlocks again = gradient_blocks(s.system, *s.model, pair);
  const double bound = distance_lower_bound(*s.model, s.data, pair);
  EXPECT_EQ(g_allocations.load() - before, 0);
  EXPECT_EQ(again.count, blocks.count);
  EXPECT_LE(bound, r.distance);
  // The counter is live: FCL itself allocates its GJK shape objects on every query.
  const long fcl_before = g_allocations.load();
  signed_distance(*s.model, *s.work, pair);
  EXPECT_GT(g_allocations.load() - fcl_before, 0);
}

}  // namespace
}  // namespace stanceplan
