// The reach rule (reach_bound.h): bounds that hold at every configuration within the limits, and
// the candidates it removes (and keeps).
#include <gtest/gtest.h>

#include <random>

#include "planner/model/kinematics.h"
#include "planner/search/candidates.h"
#include "planner/search/reach_bound.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

// The largest distance between a point of surface a and a point of surface b at q (points:
// polygon vertices; a point surface's centre, widened by its radius).
double farthest(const Scene& scene, const std::vector<ModelData>& data, SurfaceRef a,
                SurfaceRef b) {
  const Surface& sa = scene.surfaces.get(a);
  const Surface& sb = scene.surfaces.get(b);
  double d = 0.0;
  for (const Eigen::Vector3d& va : sa.vertices_L())
    for (const Eigen::Vector3d& vb : sb.vertices_L())
      d = std::max(d,
                   (data[a.entity].T_WL[sa.link] * va - data[b.entity].T_WL[sb.link] * vb).norm() +
                       (sa.is_point() ? sa.radius : 0.0) + (sb.is_point() ? sb.radius : 0.0));
  return d;
}

TEST(ReachBound, HoldsAtRandomConfigurationsWithinTheLimits) {
  const Scene scene = test::humanoid_scene("flat_ground");
  ReachTable table(scene);
  const Model& model = *scene.system.entity(0).model;
  const int n = int(scene.surfaces.of(0).size());
  std::mt19937 rng(11);
  Eigen::VectorXd q = test::standing_configuration(scene);
  const int first = scene.system.entity(0).first_dof();
  double tightest = INFINITY;  // the smallest slack seen, over every pair and sample
  for (int trial = 0; trial < 2000; ++trial) {
    for (int k = 0; k < model.num_dofs(); ++k) {
      const Joint& j = model.joints[model.dof_joints[k]];
      q[first + k] = std::uniform_real_distribution<double>(j.lower, j.upper)(rng);
    }
    const auto data = system_kinematics(scene.system, q);
    for (int a = 0; a < n; ++a)
      for (int b = a; b < n; ++b) {
        const double bound = table.between({0, a}, {0, b});
        const double d = farthest(scene, data, {0, a}, {0, b});
        ASSERT_LE(d, bound) << a << " / " << b;
        tightest = std::min(tightest, bound - d);
      }
  }
  // Not vacuous: some pair comes within 10 cm of its bound (two surfaces of one link: the stretched
  // chain has no length, only the polygons' extents count).
  EXPECT_LT(tightest, 0.1);
}

TEST(ReachBound, IsTheStretchedChainBetweenTheLinks) {
  const Scene scene = test::humanoid_scene("flat_ground");
  const Model& model = *scene.system.entity(0).model;
  const int foot = model.find_link("l_foot"), hand = model.find_link("l_hand");
  // Symmetric, zero on one link, and at least the distance at the neutral posture.
  EXPECT_DOUBLE_EQ(link_origin_reach(model, foot, hand), link_origin_reach(model, hand, foot));
  EXPECT_EQ(link_origin_reach(model, foot, foot), 0.0);
  const auto data = system_kinematics(scene.system, test::standing_configuration(scene));
  EXPECT_GE(link_origin_reach(model, foot, hand),
            (data[0].T_WL[foot].translation() - data[0].T_WL[hand].translation()).norm());
}

bool offers(const std::vector<Candidate>& list, const Scene& scene, const std::string& s1,
            const std::string& s2) {
  for (const Candidate& c : list)
    if (c.add && scene.surfaces.id(scene.system, c.contact.s1) == s1 &&
        scene.surfaces.id(scene.system, c.contact.s2) == s2)
      return true;
  return false;
}

TEST(ReachBound, CandidatesLeaveOutATreadBeyondTheLegsReach) {
  const Scene scene = test::humanoid_scene("stairs");
  // Standing on the left sole 2.85 m before the first step (tread_1 starts at x = 0.35 m).
  Eigen::VectorXd q = test::standing_configuration(scene);
  q[0] = -2.5;
  const auto data = system_kinematics(scene.system, q);
  const Contact left = test::task(scene, "robot/l_sole", "env/floor").contact;
  SearchOptions options;
  options.contact_reach = 10.0;  // the option's own pruning off: only the rule acts
  ReachTable table(scene);
  const auto ruled =
      enumerate_candidates(scene, data, Stance({left}), {}, options, nullptr, &table);
  const auto unruled = enumerate_candidates(scene, data, Stance({left}), {}, options);
  // The right sole: 2.85 m from the left one is beyond two legs' length (2.10 m, the stretched
  // chain); the floor is within it.
  const double legs =
      table.between(test::surface(scene, "robot/l_sole"), test::surface(scene, "robot/r_sole"));
  EXPECT_LT(legs, 2.2);
  EXPECT_TRUE(offers(unruled, scene, "robot/r_sole", "env/tread_1"));
  EXPECT_FALSE(offers(ruled, scene, "robot/r_sole", "env/tread_1"));
  EXPECT_FALSE(offers(ruled, scene, "robot/r_palm", "env/tread_5"));
  EXPECT_TRUE(offers(ruled, scene, "robot/r_sole", "env/floor"));
  EXPECT_TRUE(offers(ruled, scene, "robot/r_palm", "env/floor"));
  // Right before the stairs every tread is within reach: nothing of the stairs is left out.
  q[0] = 0.1;
  const auto near = enumerate_candidates(scene, system_kinematics(scene.system, q), Stance({left}),
                                         {}, options, nullptr, &table);
  EXPECT_TRUE(offers(near, scene, "robot/r_sole", "env/tread_1"));
  EXPECT_TRUE(offers(near, scene, "robot/r_palm", "env/tread_5"));
}

}  // namespace
}  // namespace stanceplan
