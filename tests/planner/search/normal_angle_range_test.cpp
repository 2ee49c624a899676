// The normal-angle rule (normal_angle_range.h): bounds that hold at every configuration within
// the limits, tight where the chain is short, and the candidates it removes.
#include <gtest/gtest.h>

#include <random>

#include "planner/model/kinematics.h"
#include "planner/search/candidates.h"
#include "planner/search/normal_angle_range.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

SurfaceRef ref(const Scene& scene, const std::string& id) {
  return *scene.surfaces.find(scene.system, id);
}

// The angle between two surfaces' normals at a configuration of the robot (entity 0).
double normal_angle(const Scene& scene, const Eigen::VectorXd& q, SurfaceRef a, SurfaceRef b) {
  const auto data = system_kinematics(scene.system, q);
  const Surface& sa = scene.surfaces.get(a);
  const Surface& sb = scene.surfaces.get(b);
  const Eigen::Vector3d na = data[0].T_WL[sa.link].linear() * sa.normal_L();
  const Eigen::Vector3d nb = data[0].T_WL[sb.link].linear() * sb.normal_L();
  return std::acos(std::clamp(na.dot(nb), -1.0, 1.0));
}

TEST(NormalAngleRange, KneeAndSoleOfOneLegAreNeverParallel) {
  const Scene scene = test::humanoid_scene("flat_ground");
  NormalAngleTable table(scene);
  const AngleRange r = table.between(ref(scene, "robot/l_knee"), ref(scene, "robot/l_sole"));
  // Knee normal +x on the shank, sole normal -z on the foot; the foot hangs on ankle pitch p in
  // [-1.25, 0.75] then roll r in [-0.5, 0.5]: cos(angle) = -sin(p) cos(r), largest at p = -1.25,
  // r = 0: the smallest angle is pi/2 - 1.25 = 0.3208 rad; the largest pi/2 + 0.75 (p = 0.75).
  const double lo = M_PI / 2 - 1.25, hi = M_PI / 2 + 0.75;
  EXPECT_LE(r.lo, lo);
  EXPECT_GT(r.lo, lo - 0.05);  // 141 x 141 grid: margin (2 + 1) / 140 / 2 = 0.011 rad
  EXPECT_GE(r.hi, hi);
  EXPECT_LT(r.hi, hi + 0.05);
  EXPECT_FALSE(r.contains(0.0, 1e-3));  // both flat on the floor: impossible
  // The two soles: a chain of twelve joints, too long for the grid: nothing is excluded.
  const AngleRange soles = table.between(ref(scene, "robot/l_sole"), ref(scene, "robot/r_sole"));
  EXPECT_EQ(soles.lo, 0.0);
  EXPECT_EQ(soles.hi, M_PI);
}

TEST(NormalAngleRange, HoldsAtRandomConfigurationsWithinTheLimits) {
  const Scene scene = test::humanoid_scene("flat_ground");
  NormalAngleTable table(scene);
  const Model& model = *scene.system.entity(0).model;
  const std::vector<std::pair<std::string, std::string>> pairs = {
      {"robot/l_knee", "robot/l_sole"},
      {"robot/r_knee", "robot/r_sole"},
      {"robot/l_thigh", "robot/l_knee"},
      {"robot/l_forearm", "robot/l_palm"}};
  std::mt19937 rng(7);
  Eigen::VectorXd q = test::standing_configuration(scene);
  const int first = scene.system.entity(0).first_dof();
  for (int trial = 0; trial < 2000; ++trial) {
    for (int k = 0; k < model.num_dofs(); ++k) {
      const Joint& j = model.joints[model.dof_joints[k]];
      q[first + k] = std::uniform_real_distribution<double>(j.lower, j.upper)(rng);
    }
    for (const auto& [a, b] : pairs) {
      const AngleRange& r = table.between(ref(scene, a), ref(scene, b));
      const double angle = normal_angle(scene, q, ref(scene, a), ref(scene, b));
      ASSERT_TRUE(r.contains(angle, 1e-12))
          << a << " / " << b << ": " << angle << " outside [" << r.lo << ", " << r.hi << "]";
    }
  }
}

bool offers_knee(const std::vector<Candidate>& list, const Scene& scene, const std::string& knee) {
  for (const Candidate& c : list)
    if (c.add && scene.surfaces.id(scene.system, c.contact.s1) == knee) return true;
  return false;
}

TEST(NormalAngleRange, CandidatesLeaveOutAKneeOnTheFloorBesideItsOwnSole) {
  const Scene scene = test::humanoid_scene("flat_ground");
  const auto data = system_kinematics(scene.system, test::standing_configuration(scene));
  const Contact left = test::task(scene, "robot/l_sole", "env/floor").contact;
  const Contact right = test::task(scene, "robot/r_sole", "env/floor").contact;
  SearchOptions options;
  options.contact_reach = 2.0;
  NormalAngleTable table(scene);
  // On both feet: neither knee can touch the floor (each beside its own flat sole).
  const auto both = enumerate_candidates(scene, data, Stance({left, right}), Stance({left, right}),
                                         options, &table);
  EXPECT_FALSE(offers_knee(both, scene, "robot/l_knee"));
  EXPECT_FALSE(offers_knee(both, scene, "robot/r_knee"));
  // Without the table the rule is off: both are offered.
  const auto unruled =
      enumerate_candidates(scene, data, Stance({left, right}), Stance({left, right}), options);
  EXPECT_TRUE(offers_knee(unruled, scene, "robot/l_knee"));
  // On the right foot: the left knee may kneel (its own sole is lifted), the right may not.
  const auto on_right =
      enumerate_candidates(scene, data, Stance({right}), Stance({left, right}), options, &table);
  EXPECT_TRUE(offers_knee(on_right, scene, "robot/l_knee"));
  EXPECT_FALSE(offers_knee(on_right, scene, "robot/r_knee"));
}

}  // namespace
}  // namespace stanceplan
