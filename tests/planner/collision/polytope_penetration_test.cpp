// The separating-axis penetration depth against hand-computed cases, against FCL's EPA on random
// generic overlaps (where EPA is exact on polytopes and does not hit its abort), and on the
// nearly-parallel contacts that make FCL's EPA abort.
#include <fcl/geometry/shape/box.h>
#include <fcl/geometry/shape/convex.h>
#include <fcl/narrowphase/distance.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <random>

#include "planner/collision/convex_hull.h"
#include "planner/collision/polytope_penetration.h"
#include "planner/model/mesh_file.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

Eigen::Isometry3d pose(const Eigen::Quaterniond& q, const Eigen::Vector3d& t) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.normalized().toRotationMatrix();
  T.translation() = t;
  return T;
}

// A TALOS collision mesh's hull, centred on the origin.
ConvexHull centred_talos_hull(const std::string& relative) {
  std::vector<Eigen::Vector3d> points =
      load_mesh(test::shared_path("robots/talos/robots/talos_data/meshes/" + relative)).vertices;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& p : points) mean += p;
  mean /= static_cast<double>(points.size());
  for (auto& p : points) p -= mean;
  return convex_hull(points);
}

std::shared_ptr<fcl::Convexd> fcl_convex(const ConvexHull& hull) {
  auto vertices = std::make_shared<std::vector<Eigen::Vector3d>>(hull.vertices);
  auto faces = std::make_shared<std::vector<int>>();
  for (const Eigen::Vector3i& t : hull.triangles)
    faces->insert(faces->end(), {3, t[0], t[1], t[2]});
  return std::make_shared<fcl::Convexd>(vertices, static_cast<int>(hull.triangles.size()), faces);
}

TEST(PolytopePenetration, BoxStructure) {
  const ConvexPolytope box = polytope_from_box(Eigen::Vector3d(0.2, 0.4, 0.6));
  EXPECT_EQ(box.vertices.size(), 8u);
  EXPECT_EQ(box.planes.size(), 6u);
  EXPECT_EQ(box.edges.size(), 12u);
  for (const auto& e : box.edges) {
    // The edge lies on both of its faces.
    for (const Eigen::Vector3d* n : {&e.n0, &e.n1}) {
      const double support = n->cwiseAbs().dot(Eigen::Vector3d(0.1, 0.2, 0.3));
      EXPECT_NEAR(n->dot(box.vertices[e.v0]), support, 1e-15);
      EXPECT_NEAR(n->dot(box.vertices[e.v1]), support, 1e-15);
    }
  }
  // A hull of the same box gives the same structure (coplanar triangles merged).
  const ConvexPolytope from_hull = polytope_from_hull(convex_hull(box.vertices));
  EXPECT_EQ(from_hull.planes.size(), 6u);
  EXPECT_EQ(from_hull.edges.size(), 12u);
}

TEST(PolytopePenetration, FaceAndEdgeContactsByHand) {
  const ConvexPolytope cube = polytope_from_box(Eigen::Vector3d(1, 1, 1));
  // Face contact: B 0.9 above A along z (overlap 0.1), turned about z.
  PenetrationScratch scratch;
  Penetration p = polytope_penetration(
      cube, Eigen::Isometry3d::Identity(), cube,
      pose(Eigen::Quaterniond(Eigen::AngleAxisd(0.3, Eigen::Vector3d::UnitZ())), {0.05, 0, 0.9}),
      scratch);
  EXPECT_NEAR(p.depth, 0.1, 1e-12);
  EXPECT_NEAR((p.normal_W - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(p.normal_W.dot(p.p_B_W - p.p_A_W), -p.depth, 1e-12);
  // Edge-edge contact: A turned 45 degrees about x (top edge along x at z = sqrt(1/2)), B turned
  // 45 degrees about y (bottom edge along y), the two edges 0.05 into each other along z.
  const double half_diagonal = std::sqrt(0.5);
  const Eigen::Isometry3d T_WA =
      pose(Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitX())), {0, 0, 0});
  const Eigen::Isometry3d T_WB =
      pose(Eigen::Quaterniond(Eigen::AngleAxisd(M_PI / 4, Eigen::Vector3d::UnitY())),
           {0, 0, 2 * half_diagonal - 0.05});
  p = polytope_penetration(cube, T_WA, cube, T_WB, scratch);
  EXPECT_NEAR(p.depth, 0.05, 1e-12);
  EXPECT_NEAR((p.normal_W - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_NEAR((p.p_A_W - Eigen::Vector3d(0, 0, half_diagonal)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((p.p_B_W - Eigen::Vector3d(0, 0, half_diagonal - 0.05)).norm(), 0.0, 1e-12);
}

TEST(PolytopePenetration, MatchesFclEpaOnRandomOverlaps) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const ConvexHull arm = centred_talos_hull("arm/arm_3_collision.STL");
  const ConvexHull knee = centred_talos_hull("v2/knee_collision.stl");
  const Eigen::Vector3d box_size(0.1, 0.15, 0.2);
  struct Case {
    const char* name;
    ConvexPolytope a, b;
    std::shared_ptr<fcl::CollisionGeometryd> fcl_a, fcl_b;
  };
  const std::vector<Case> cases = {
      {"box-box", polytope_from_box(box_size), polytope_from_box(box_size),
       std::make_shared<fcl::Boxd>(box_size), std::make_shared<fcl::Boxd>(box_size)},
      {"box-hull", polytope_from_box(box_size), polytope_from_hull(arm),
       std::make_shared<fcl::Boxd>(box_size), fcl_convex(arm)},
      {"hull-hull", polytope_from_hull(arm), polytope_from_hull(knee), fcl_convex(arm),
       fcl_convex(knee)}};
  fcl::DistanceRequestd request;
  request.enable_nearest_points = true;
  request.enable_signed_distance = true;
  request.gjk_solver_type = fcl::GST_LIBCCD;
  request.distance_tolerance = 1e-9;
  PenetrationScratch scratch;
  std::mt19937 rng(3);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (const Case& c : cases) {
    int compared = 0;
    double worst = 0.0;
    for (int i = 0; i < 300; ++i) {
      const Eigen::Isometry3d T_WA =
          pose(Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)), {0, 0, 0});
      const Eigen::Isometry3d T_WB =
          pose(Eigen::Quaterniond(normal(rng), normal(rng), normal(rng), normal(rng)),
               0.05 * Eigen::Vector3d(normal(rng), normal(rng), normal(rng)));
      fcl::DistanceResultd epa;
      fcl::distance(c.fcl_a.get(), T_WA, c.fcl_b.get(), T_WB, request, epa);
      if (epa.min_distance >= 0.0) continue;
      const Penetration p = polytope_penetration(c.a, T_WA, c.b, T_WB, scratch);
      ++compared;
      worst = std::max(worst, std::abs(-p.depth - epa.min_distance));
      EXPECT_NEAR(-p.depth, epa.min_distance, 1e-12) << c.name << " #" << i;
      EXPECT_NEAR(p.normal_W.dot(p.p_B_W - p.p_A_W), -p.depth, 1e-9) << c.name << " #" << i;
    }
    std::printf("[ %-9s ] %d overlaps, max |SAT - EPA| = %.2e\n", c.name, compared, worst);
    EXPECT_GE(compared, 100) << c.name;
  }
}

TEST(PolytopePenetration, NearlyParallelFacesOnAFloor) {
  // The configurations that abort FCL's EPA: a slightly tilted box 1e-7..1e-2 m deep in a large
  // floor box. The depth is that of the lowest corner.
  const ConvexPolytope floor = polytope_from_box(Eigen::Vector3d(4, 4, 0.1));
  const Eigen::Vector3d size(0.21, 0.13, 0.02);
  const ConvexPolytope sole = polytope_from_box(size);
  const Eigen::Isometry3d T_W_floor = pose(Eigen::Quaterniond::Identity(), {0, 0, -0.05});
  PenetrationScratch scratch;
  std::mt19937 rng(5);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::uniform_real_distribution<double> exponent(-7.0, -2.0);
  for (int i = 0; i < 2000; ++i) {
    const Eigen::Vector3d axis =
        Eigen::Vector3d(normal(rng), normal(rng), normal(rng)).normalized();
    const double tilt = std::pow(10.0, exponent(rng));
    const Eigen::Quaterniond q(Eigen::AngleAxisd(tilt, axis) *
                               Eigen::AngleAxisd(normal(rng), Eigen::Vector3d::UnitZ()));
    const double depth = std::pow(10.0, exponent(rng));
    Eigen::Isometry3d T_WS = pose(q, {0.3 * normal(rng), 0.3 * normal(rng), 0});
    double lowest = 1e9;
    for (const auto& v : sole.vertices) lowest = std::min(lowest, (T_WS * v).z());
    T_WS.translation().z() -= lowest + depth;
    const Penetration p = polytope_penetration(floor, T_W_floor, sole, T_WS, scratch);
    ASSERT_NEAR(p.depth, depth, 1e-12) << "#" << i;
    ASSERT_NEAR((p.normal_W - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-12) << "#" << i;
  }
}

}  // namespace
}  // namespace stanceplan
