// Surfaces from a link's collision geometry (surface files' `face:`): the faces of boxes,
// cylinders and meshes (tests/data/link_faces/: a turned box, a foot mesh with a flat bottom and a
// dented top, a sphere, a cylinder, a tilted cube, an ankle block over a sole plate), the faults
// with their messages, and the hull-face helpers they are built on.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "planner/contact/hull_face.h"
#include "planner/contact/link_faces.h"
#include "planner/contact/surface_file.h"
#include "planner/model/urdf_loader.h"
#include "planner/util/input_error.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

Model faces_model() {
  return load_urdf(test::source_path("tests/data/link_faces/faces.urdf"));
}

Eigen::Vector3d axis(const std::string& name) {
  const int i = std::string("xyz").find(name[1]);
  return (name[0] == '+' ? 1.0 : -1.0) * Eigen::Vector3d::Unit(i);
}

Surface face_surface(const Model& model, const std::string& link, const std::string& face,
                     double inset = 0.0, const Eigen::Vector3d* x_axis = nullptr) {
  return surface_from_link_face(model, model.find_link(link), axis(face), face, inset, x_axis, "s");
}

std::string face_error(const Model& model, const std::string& link, const Eigen::Vector3d& d,
                       const std::string& label, double inset = 0.0) {
  try {
    surface_from_link_face(model, model.find_link(link), d, label, inset, nullptr, "s");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// True when every vertex of a has a vertex of b within `tolerance` (m) and the counts agree.
bool same_vertex_set(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
                     double tolerance = 1e-12) {
  if (a.size() != b.size()) return false;
  return std::all_of(a.begin(), a.end(), [&](const Eigen::Vector3d& p) {
    return std::any_of(b.begin(), b.end(),
                       [&](const Eigen::Vector3d& q) { return (p - q).norm() < tolerance; });
  });
}

// Mesh vertices are read in single precision (assimp): 1e-8 m of round-off.
constexpr double kMeshPrecision = 1e-7;

TEST(LinkFaces, EveryFaceOfATurnedBoxMatchesItsBoxFace) {
  const Model model = faces_model();
  // The box is turned a quarter turn about z: its own +x axis is the link's +y.
  const std::pair<const char*, const char*> link_to_box[] = {
      {"+x", "-y"}, {"-x", "+y"}, {"+y", "+x"}, {"-y", "-x"}, {"+z", "+z"}, {"-z", "-z"}};
  for (const auto& [link_face, box] : link_to_box) {
    const Surface face = face_surface(model, "base", link_face);
    const Surface expected = surface_from_box_face(model, 0, 0, box, 0.0, "s");
    EXPECT_TRUE(face.normal_L().isApprox(axis(link_face), 1e-12)) << link_face;
    EXPECT_TRUE(face.normal_L().isApprox(expected.normal_L(), 1e-12)) << link_face;
    EXPECT_TRUE(same_vertex_set(face.vertices_L(), expected.vertices_L())) << link_face;
    EXPECT_NEAR(face.area(), expected.area(), 1e-12) << link_face;
  }
  // The bottom face of the 0.3 x 0.2 x 0.1 box at z = 0.2: 0.2 along the link's x, 0.3 along y.
  const Surface bottom = face_surface(model, "base", "-z");
  EXPECT_NEAR(bottom.T_LS.translation().z(), 0.15, 1e-12);
  EXPECT_NEAR(bottom.area(), 0.06, 1e-12);
  // x axis by the one rule: the link's x, projected.
  EXPECT_TRUE(bottom.T_LS.linear().col(0).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
}

TEST(LinkFaces, MeshFootGivesItsFlatBottomWithoutCollinearVertices) {
  const Model model = faces_model();
  const Surface sole = face_surface(model, "foot", "-z");
  EXPECT_TRUE(sole.normal_L().isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  // The chamfered footprint's 8 corners; the vertices halfway along the long sides are dropped.
  const std::vector<Eigen::Vector3d> corners = {
      {0.13, -0.04, -0.1}, {0.13, 0.04, -0.1},   {0.11, 0.06, -0.1},   {-0.07, 0.06, -0.1},
      {-0.09, 0.04, -0.1}, {-0.09, -0.04, -0.1}, {-0.07, -0.06, -0.1}, {0.11, -0.06, -0.1}};
  EXPECT_TRUE(same_vertex_set(sole.vertices_L(), corners, kMeshPrecision));
  EXPECT_NEAR(sole.area(), 0.22 * 0.12 - 4 * 0.5 * 0.02 * 0.02, kMeshPrecision);
  EXPECT_NEAR((sole.T_LS.translation() - Eigen::Vector3d(0.02, 0, -0.1)).norm(), 0.0,
              kMeshPrecision);
  EXPECT_TRUE(sole.T_LS.linear().col(0).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
}

TEST(LinkFaces, InsetMovesEveryEdgeInward) {
  const Model model = faces_model();
  const Surface sole = face_surface(model, "foot", "-z", 0.005);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (const Eigen::Vector3d& v : sole.vertices_L()) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  EXPECT_NEAR(lo.x(), -0.085, kMeshPrecision);
  EXPECT_NEAR(hi.x(), 0.125, kMeshPrecision);
  EXPECT_NEAR(lo.y(), -0.055, kMeshPrecision);
  EXPECT_NEAR(hi.y(), 0.055, kMeshPrecision);
  EXPECT_EQ(sole.vertices_S.size(), 8u);
  EXPECT_EQ(face_error(model, "foot", axis("-z"), "-z", 0.06),
            "inset 0.06 m leaves nothing of face -z of link \"foot\" (mesh foot.obj; the face is "
            "0.12 m across at its narrowest)");
}

TEST(LinkFaces, DentedMeshTopIsNoFlatFace) {
  // The dent's triangles face up (22 degrees off +z) but are not on the convex hull; the hull's
  // triangles nearest +z are the sloped toe and heel sides, 50.48 degrees off.
  const std::string error = face_error(faces_model(), "foot", axis("+z"), "+z");
  EXPECT_THAT(error, HasSubstr("link \"foot\" has no flat face within 30 degrees of +z: the "
                               "nearest outward normal is ["));
  EXPECT_THAT(error, HasSubstr(", 0, 0.6364] (50.48 degrees away, link frame); its collision "
                               "geometry is mesh foot.obj"));
}

TEST(LinkFaces, CylinderCapIsTheInscribedSixteenGon) {
  const Model model = faces_model();
  const Surface cap = face_surface(model, "can", "-z");
  ASSERT_EQ(cap.vertices_S.size(), 16u);
  for (const Eigen::Vector3d& v : cap.vertices_L()) {
    EXPECT_NEAR(v.head<2>().norm(), 0.04, 1e-12);
    EXPECT_NEAR(v.z(), -0.05, 1e-12);
  }
  EXPECT_NEAR(cap.area(), 8 * 0.04 * 0.04 * std::sin(2 * M_PI / 16), 1e-12);
  EXPECT_TRUE(cap.vertex_L(0).isApprox(Eigen::Vector3d(0.04, 0, -0.05), 1e-12));
  EXPECT_EQ(face_error(model, "can", axis("+x"), "+x"),
            "link \"can\" has no flat face within 30 degrees of +x: the nearest outward normal is "
            "[0, 0, 1] (90 degrees away, link frame); its collision geometry is cylinder of "
            "radius 0.04 m and length 0.1 m");
}

TEST(LinkFaces, SphereOnlyAndBareLinksHaveNoFace) {
  const Model model = faces_model();
  EXPECT_EQ(face_error(model, "ball", axis("-z"), "-z"),
            "link \"ball\" has no flat face: its collision geometry is sphere of radius 0.05 m");
  EXPECT_EQ(face_error(model, "ball_on_stick", axis("-z"), "-z"),
            "link \"ball_on_stick\" has no flat face: its collision geometry is sphere of radius "
            "0.03 m, sphere of radius 0.02 m");
  EXPECT_EQ(face_error(model, "bare", axis("-z"), "-z"),
            "link \"bare\" has no collision geometry to take a face from");
}

TEST(LinkFaces, FaceFurtherThanThirtyDegreesIsRefused) {
  // The cube turned 45 degrees about x: towards [0, 0.2, -1] its nearest face is 33.69 degrees off.
  EXPECT_EQ(face_error(faces_model(), "tilted", Eigen::Vector3d(0, 0.2, -1), "[0, 0.2, -1]"),
            "link \"tilted\" has no flat face within 30 degrees of [0, 0.2, -1]: the nearest "
            "outward normal is [0, 0.7071, -0.7071] (33.69 degrees away, link frame); its "
            "collision geometry is box 0.1 x 0.1 x 0.1 m");
  // Towards -z two faces are 45 degrees off, equally far along it: the first one.
  EXPECT_EQ(face_error(faces_model(), "tilted", axis("-z"), "-z"),
            "link \"tilted\" has no flat face within 30 degrees of -z: the nearest outward normal "
            "is [0, -0.7071, -0.7071] (45 degrees away, link frame); its collision geometry is "
            "box 0.1 x 0.1 x 0.1 m");
  // Towards [0, 0.5, -1] it is 18.43 degrees off: taken.
  const Model model = faces_model();
  const Surface s =
      surface_from_link_face(model, model.find_link("tilted"), Eigen::Vector3d(0, 0.5, -1),
                             "[0, 0.5, -1]", 0.0, nullptr, "s");
  EXPECT_TRUE(s.normal_L().isApprox(Eigen::Vector3d(0, M_SQRT1_2, -M_SQRT1_2), 1e-12));
}

TEST(LinkFaces, TiedFacesGoToTheOneReachingFurthest) {
  const Model model = faces_model();
  const Surface bottom = face_surface(model, "ankle_and_plate", "-z");  // the plate's
  EXPECT_NEAR(bottom.T_LS.translation().z(), -0.1, 1e-12);
  EXPECT_NEAR(bottom.area(), 0.22 * 0.13, 1e-12);
  const Surface top = face_surface(model, "ankle_and_plate", "+z");  // the block's
  EXPECT_NEAR(top.T_LS.translation().z(), -0.03, 1e-12);
  EXPECT_NEAR(top.area(), 0.08 * 0.07, 1e-12);
  EXPECT_EQ(nearest_link_face(model, model.find_link("ankle_and_plate"), axis("-z"), "-z").geometry,
            1);
}

TEST(LinkFaces, GivenXAxisIsProjectedOnTheFace) {
  const Model model = faces_model();
  const Eigen::Vector3d x_axis(0.1, 1.0, 0.5);
  const Surface sole = face_surface(model, "foot", "-z", 0.0, &x_axis);
  EXPECT_TRUE(sole.T_LS.linear().col(0).isApprox(Eigen::Vector3d(0.1, 1, 0).normalized(), 1e-12));
  EXPECT_NEAR(sole.T_LS.linear().determinant(), 1.0, 1e-12);
}

TEST(HullFace, ConvexHull2dDropsInnerRepeatedAndCollinearPoints) {
  const Polygon2 hull = convex_hull_2d(
      {{0, 0}, {1, 0}, {0.5, 0}, {1, 1}, {0, 1}, {0.5, 0.5}, {1, 1}, {0, 0.5}, {0.2, 0.7}});
  ASSERT_EQ(hull.size(), 4u);
  EXPECT_TRUE(hull[0].isApprox(Eigen::Vector2d(0, 0)));
  EXPECT_TRUE(hull[1].isApprox(Eigen::Vector2d(1, 0)));
  EXPECT_TRUE(hull[2].isApprox(Eigen::Vector2d(1, 1)));
  EXPECT_TRUE(hull[3].isApprox(Eigen::Vector2d(0, 1)));
  EXPECT_EQ(convex_hull_2d({{0, 0}, {1, 1}, {2, 2}}).size(), 2u);
}

TEST(HullFace, PointsWithinTheFlatnessOfTheSupportPlaneMakeOneFace) {
  // A square rim at z = 0 around a centre 1 mm lower: one face within 2 mm, on the lowest plane.
  const std::vector<Eigen::Vector3d> points = {{0.1, 0.1, 0},  {-0.1, 0.1, 0}, {-0.1, -0.1, 0},
                                               {0.1, -0.1, 0}, {0, 0, -0.001}, {0, 0, 0.05}};
  const PlanarFace face = support_face(points, Eigen::Vector3d(0, 0, -1), 2e-3, 1e-4);
  ASSERT_EQ(face.vertices.size(), 4u);
  EXPECT_NEAR(face.offset, 0.001, 1e-15);
  for (const Eigen::Vector3d& v : face.vertices) EXPECT_NEAR(v.z(), -0.001, 1e-15);
  EXPECT_NEAR(narrowest_width(face), 0.2, 1e-12);
  // Within 0.5 mm only the centre: no face.
  EXPECT_TRUE(support_face(points, Eigen::Vector3d(0, 0, -1), 5e-4, 1e-4).vertices.empty());
}

TEST(HullFace, NearestHullNormalSkipsTrianglesOffTheHullAndTrustsNoWinding) {
  // A tetrahedron with its base wound the wrong way, and a dent: a triangle pointing straight up
  // from inside the hull.
  const std::vector<Eigen::Vector3d> v = {{0, 0, 0},      {1, 0, 0},       {0, 1, 0},
                                          {0, 0, 1},      {0.1, 0.1, 0.1}, {0.2, 0.1, 0.1},
                                          {0.1, 0.2, 0.1}};
  const std::vector<Eigen::Vector3i> t = {{0, 1, 2}, {0, 1, 3}, {1, 2, 3}, {0, 2, 3}, {4, 5, 6}};
  const auto down = nearest_hull_normal(v, t, Eigen::Vector3d(0, 0, -1), 1e-9);
  ASSERT_TRUE(down.has_value());
  EXPECT_TRUE(down->isApprox(Eigen::Vector3d(0, 0, -1), 1e-12));
  const auto up = nearest_hull_normal(v, t, Eigen::Vector3d(0, 0, 1), 1e-9);
  ASSERT_TRUE(up.has_value());
  EXPECT_TRUE(up->isApprox(Eigen::Vector3d(1, 1, 1).normalized(), 1e-12));
}

}  // namespace
}  // namespace stanceplan
