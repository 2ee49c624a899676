// Contact surfaces: construction, validation faults with their messages, the surface file loader
// and surfaces derived from box faces.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/support/paths.h"

#include <filesystem>
#include <fstream>

#include "planner/contact/surface_file.h"
#include "planner/model/urdf_loader.h"
#include "planner/util/input_error.h"
#include "tests/support/test_models.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

std::vector<Eigen::Vector3d> square(double z, bool ccw_about_minus_z) {
  std::vector<Eigen::Vector3d> v = {
      {0.1, 0.05, z}, {-0.1, 0.05, z}, {-0.1, -0.05, z}, {0.1, -0.05, z}};
  if (ccw_about_minus_z) std::reverse(v.begin(), v.end());
  return v;
}

std::string make_error(const std::vector<Eigen::Vector3d>& v, const Eigen::Vector3d& n) {
  Surface s;
  std::string error;
  EXPECT_FALSE(make_surface("s", 0, "base", v, n, nullptr, &s, &error));
  return error;
}

TEST(Surface, SoleFrameAndPolygon) {
  Surface s;
  std::string error;
  ASSERT_TRUE(make_surface("sole", 0, "foot", square(-0.1, true), Eigen::Vector3d(0, 0, -1),
                           nullptr, &s, &error))
      << error;
  EXPECT_TRUE(s.normal_L().isApprox(Eigen::Vector3d(0, 0, -1)));
  EXPECT_TRUE(s.T_LS.linear().col(0).isApprox(Eigen::Vector3d(1, 0, 0)));  // link x, projected
  EXPECT_NEAR(s.T_LS.linear().determinant(), 1.0, 1e-12);
  EXPECT_TRUE(s.T_LS.translation().isApprox(Eigen::Vector3d(0, 0, -0.1)));
  EXPECT_NEAR(s.area(), 0.2 * 0.1, 1e-12);
  EXPECT_NEAR(s.centroid_S().norm(), 0.0, 1e-12);
  const auto back = s.vertices_L();
  const auto given = square(-0.1, true);
  for (size_t i = 0; i < given.size(); ++i) EXPECT_NEAR((back[i] - given[i]).norm(), 0.0, 1e-12);
}

TEST(Surface, ClockwiseIsRejected) {
  EXPECT_THAT(make_error(square(0.0, false), Eigen::Vector3d(0, 0, -1)),
              HasSubstr("clockwise about the outward normal"));
}

TEST(Surface, NonPlanarIsRejected) {
  auto v = square(0.0, false);
  v[2].z() = 0.01;
  EXPECT_THAT(make_error(v, Eigen::Vector3d(0, 0, 1)), HasSubstr("not planar: vertex 2 is"));
}

TEST(Surface, NonConvexIsRejected) {
  std::vector<Eigen::Vector3d> v = {{0, 0, 0}, {1, 0, 0}, {0.3, 0.3, 0}, {1, 1, 0}, {0, 1, 0}};
  EXPECT_THAT(make_error(v, Eigen::Vector3d(0, 0, 1)),
              HasSubstr("not strictly convex at vertex 2"));
}

TEST(Surface, SelfIntersectingStarIsRejected) {
  std::vector<Eigen::Vector3d> v;
  for (int i = 0; i < 5; ++i) {
    const double a = 2.0 * M_PI * (2 * i) / 5.0;  // pentagram: every second vertex of a pentagon
    v.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  EXPECT_THAT(make_error(v, Eigen::Vector3d(0, 0, 1)), HasSubstr("self-intersecting"));
}

TEST(Surface, TooFewVerticesAndDuplicatesAreRejected) {
  EXPECT_THAT(make_error({{0, 0, 0}, {1, 0, 0}}, Eigen::Vector3d(0, 0, 1)),
              HasSubstr("at least 3 vertices, found 2"));
  EXPECT_THAT(make_error({{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}}, Eigen::Vector3d(0, 0, 1)),
              HasSubstr("vertex 1 and vertex 2 coincide"));
}

class SurfaceFile : public ::testing::Test {
 protected:
  void SetUp() override {
    model_ = load_urdf_string(test::kBranchingUrdf, ".");
    const auto dir = test::temp_dir("surfaces");
    std::filesystem::create_directories(dir);
    path_ = (dir / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) +
                    ".yaml"))
                .string();
  }
  std::string write(const std::string& text) {
    std::ofstream(path_) << text;
    return path_;
  }
  std::string error_of(const std::string& text) {
    write(text);
    try {
      load_surface_file(path_, model_);
    } catch (const InputError& e) {
      return e.what();
    }
    return "";
  }
  Model model_;
  std::string path_;
};

TEST_F(SurfaceFile, LoadsPolygonAndBoxFaceSurfaces) {
  const auto surfaces = load_surface_file(write(R"(format: stanceplan/surfaces@1
surfaces:
  - name: pad
    link: a4
    normal: [0, 0, 1]
    vertices: [[0.02, 0.02, 0.1], [-0.02, 0.02, 0.1], [-0.02, -0.02, 0.1], [0.02, -0.02, 0.1]]
  - name: bottom
    link: base
    box_face: -z
    inset: 0.01
)"),
                                          model_);
  ASSERT_EQ(surfaces.size(), 2u);
  EXPECT_EQ(surfaces[0].link, model_.find_link("a4"));
  EXPECT_NEAR(surfaces[0].area(), 0.0016, 1e-12);
  EXPECT_TRUE(surfaces[1].normal_L().isApprox(Eigen::Vector3d(0, 0, -1)));
  EXPECT_NEAR(surfaces[1].T_LS.translation().z(), -0.05, 1e-12);  // box 0.3 x 0.2 x 0.1
  EXPECT_NEAR(surfaces[1].area(), 0.28 * 0.18, 1e-12);
}

TEST_F(SurfaceFile, EveryBoxFaceIsCounterClockwiseAboutItsOutwardNormal) {
  for (const std::string face : {"+x", "-x", "+y", "-y", "+z", "-z"}) {
    const Surface s = surface_from_box_face(model_, 0, 0, face, 0.0, "f");
    const Eigen::Vector3d n = s.normal_L();
    // Outward: the face centre lies along the normal from the box centre.
    EXPECT_GT(s.T_LS.translation().dot(n), 0.0) << face;
    EXPECT_GT(s.area(), 0.0) << face;
  }
}

TEST_F(SurfaceFile, UnknownLinkIsNamedWithFileAndLine) {
  const std::string text = R"(format: stanceplan/surfaces@1
surfaces:
  - name: palm
    link: hand
    normal: [0, 0, 1]
    vertices: [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
)";
  EXPECT_EQ(error_of(text),
            path_ + ":4: surface \"palm\": link \"hand\" is not in model \"branching\"");
}

TEST_F(SurfaceFile, NonConvexPolygonIsNamed) {
  const std::string text = R"(format: stanceplan/surfaces@1
surfaces:
  - name: dart
    link: base
    normal: [0, 0, 1]
    vertices: [[0, 0, 0], [1, 0, 0], [0.3, 0.3, 0], [1, 1, 0], [0, 1, 0]]
)";
  EXPECT_EQ(error_of(text), path_ +
                                ":6: surface \"dart\": the polygon is not strictly convex at "
                                "vertex 2 (a right turn)");
}

TEST_F(SurfaceFile, WrongFormatMissingFieldsAndBadNumbers) {
  EXPECT_EQ(error_of("format: other\nsurfaces: []\n"),
            path_ + ":1: format: expected \"stanceplan/surfaces@1\", found \"other\"");
  EXPECT_THAT(error_of("format: stanceplan/surfaces@1\nsurfaces:\n  - name: a\n    link: base\n"),
              HasSubstr(":3: surface \"a\": vertices: missing (or give box_face, face or point)"));
  EXPECT_THAT(error_of("format: stanceplan/surfaces@1\nsurfaces:\n  - name: a\n    link: base\n"
                       "    normal: [0, 0, one]\n    vertices: [[0,0,0],[1,0,0],[0,1,0]]\n"),
              HasSubstr(":5: surface \"a\": normal: expected a number, found \"one\""));
  EXPECT_THAT(
      error_of("format: stanceplan/surfaces@1\nsurfaces:\n  - name: a\n    link: base\n"
               "    box_face: +w\n"),
      HasSubstr(":5: surface \"a\": box_face: expected one of +x -x +y -y +z -z, found \"+w\""));
  EXPECT_THAT(error_of("format: stanceplan/surfaces@1\nsurfaces:\n  - name: a\n    link: a1\n"
                       "    box_face: +z\n"),
              HasSubstr("link \"a1\" has 0 collision box(es), box_index 0 does not exist"));
  EXPECT_THAT(error_of("format: [unclosed\n"), HasSubstr(": not valid YAML"));
}

TEST_F(SurfaceFile, DuplicateNamesAreRejected) {
  const std::string text = R"(format: stanceplan/surfaces@1
surfaces:
  - {name: a, link: base, box_face: +z}
  - {name: a, link: base, box_face: -z}
)";
  EXPECT_EQ(error_of(text), path_ + ":4: surface \"a\": the name is used twice");
}

TEST(SurfaceFileMissing, MissingFileIsNamed) {
  const Model model = load_urdf_string(test::kBranchingUrdf, ".");
  try {
    load_surface_file("/nonexistent/s.yaml", model);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "/nonexistent/s.yaml: no such file");
  }
}

}  // namespace
}  // namespace stanceplan
