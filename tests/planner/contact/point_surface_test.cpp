// Point surfaces (a sphere at a point of a link, e.g. a round fingertip): construction, what they
// present to code written for polygons (one vertex, the centre), and the surface file's `point` and
// `radius` fields with their exact faults.
#include <gtest/gtest.h>

#include <fstream>

#include "planner/contact/surface_file.h"
#include "planner/model/urdf_loader.h"
#include "planner/util/input_error.h"
#include "tests/support/paths.h"

#include "tests/support/surface_file_fixture.h"

namespace stanceplan {
namespace {

TEST(PointSurface, IsASphereWhoseCentreIsItsOnlyVertex) {
  Surface s;
  std::string error;
  ASSERT_TRUE(
      make_point_surface("tip", 3, "distal", Eigen::Vector3d(0.01, 0.0, 0.03), 0.008, &s, &error))
      << error;
  EXPECT_TRUE(s.is_point());
  EXPECT_EQ(s.kind, SurfaceKind::Point);
  EXPECT_EQ(s.name, "tip");
  EXPECT_EQ(s.link, 3);
  EXPECT_EQ(s.link_name, "distal");
  EXPECT_DOUBLE_EQ(s.radius, 0.008);
  EXPECT_TRUE(s.center_L().isApprox(Eigen::Vector3d(0.01, 0.0, 0.03)));
  EXPECT_TRUE(s.T_LS.linear().isIdentity());
  ASSERT_EQ(s.vertices_S.size(), 1u);
  EXPECT_TRUE(s.vertex_L(0).isApprox(s.center_L()));  // the centre stands for s1's vertices
  EXPECT_EQ(s.area(), 0.0);
  EXPECT_TRUE(s.centroid_S().isZero());
  // A polygon surface is of kind Polygon by default.
  EXPECT_FALSE(Surface{}.is_point());
}

TEST(PointSurface, NegativeOrNonFiniteValuesAreRefused) {
  Surface s;
  std::string error;
  EXPECT_FALSE(make_point_surface("tip", 0, "l", Eigen::Vector3d::Zero(), -0.01, &s, &error));
  EXPECT_EQ(error, "the radius must be a length >= 0 (m), found -0.010000");
  EXPECT_FALSE(make_point_surface("tip", 0, "l", Eigen::Vector3d(0, NAN, 0), 0.01, &s, &error));
  EXPECT_EQ(error, "the point is not finite");
  EXPECT_TRUE(make_point_surface("tip", 0, "l", Eigen::Vector3d::Zero(), 0.0, &s, &error));
}

class PointSurfaceFile : public test::SurfaceFileTest {};

TEST_F(PointSurfaceFile, LoadsBesideAPolygon) {
  const std::vector<Surface> s = load(
      "  - {name: sole, link: foot, face: -z}\n"
      "  - {name: tip, link: ball, point: [0, 0.01, -0.02], radius: 0.05}\n");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_FALSE(s[0].is_point());
  ASSERT_TRUE(s[1].is_point());
  EXPECT_EQ(s[1].link, model_.find_link("ball"));
  EXPECT_TRUE(s[1].center_L().isApprox(Eigen::Vector3d(0, 0.01, -0.02)));
  EXPECT_DOUBLE_EQ(s[1].radius, 0.05);
}

TEST_F(PointSurfaceFile, FaultsAreNamedWithTheirLine) {
  EXPECT_EQ(error_of("  - {name: tip, link: ball, point: [0, 0, 0], radius: 0.01, x_axis: [1, 0, "
                     "0]}\n"),
            path_ +
                ":3: surfaces[0].x_axis: not a field of a point surface (expected one of: name, "
                "link, point, radius)");
  EXPECT_EQ(error_of("  - {name: tip, link: ball, point: [0, 0, 0], radius: 0.01, size: 2}\n"),
            path_ +
                ":3: surfaces[0].size: unknown field (expected one of: name, link, point, "
                "radius)");
  EXPECT_EQ(error_of("  - {name: tip, link: ball, point: [0, 0, 0]}\n"),
            path_ +
                ":3: surface \"tip\": radius: missing (the radius of the sphere at the point, m; 0 "
                "for a tip)");
  EXPECT_EQ(error_of("  - name: tip\n    link: ball\n    point: [0, 0, 0]\n    radius: -0.01\n"),
            path_ + ":6: surface \"tip\": radius: expected a length >= 0 (m), found -0.01");
  EXPECT_EQ(error_of("  - name: tip\n    link: ball\n    point: [0, 0]\n    radius: 0.01\n"),
            path_ + ":5: surface \"tip\": point: expected [x, y, z]");
  EXPECT_EQ(error_of("  - {name: tip, link: ball, point: [0, 0, 0], radius: 0.01, vertices: []}\n"),
            path_ +
                ":3: surfaces[0]: give one of vertices, box_face, face or point, found "
                "vertices and point");
  EXPECT_EQ(error_of("  - {name: tip, link: ball, point: [0, 0, 0], radius: big}\n"),
            path_ + ":3: surface \"tip\": radius: expected a number, found \"big\"");
}

}  // namespace
}  // namespace stanceplan
