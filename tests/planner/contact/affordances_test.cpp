// Surfaces extracted from collision geometry (planner/contact/affordances.h): classes, convex
// pieces, the slope limit, deterministic names, the coplanar merge tolerances.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "planner/contact/affordances.h"
#include "planner/contact/planar_regions.h"
#include "planner/contact/polygon.h"
#include "planner/model/urdf_loader.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

namespace fs = std::filesystem;
using Eigen::Vector3d;

// A one-link environment whose collision geometry is `geometry` (URDF elements) at `origin`.
Model one_link(const std::string& geometry, const std::string& origin = "0 0 0",
               const std::string& rpy = "0 0 0", const std::string& name = "thing") {
  const fs::path path = test::temp_dir("affordances") / (name + ".urdf");
  std::ofstream(path) << "<robot name=\"" << name << "\"><link name=\"body\"><inertial><mass "
                      << "value=\"1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" iyy=\"1\" iyz=\"0\" "
                      << "izz=\"1\"/></inertial><collision><origin xyz=\"" << origin << "\" rpy=\""
                      << rpy << "\"/><geometry>" << geometry
                      << "</geometry></collision></link></robot>\n";
  return load_urdf(path.string());
}

// An ASCII STL of the given triangles (counter-clockwise seen from outside).
std::string write_stl(const std::string& name, const std::vector<std::array<Vector3d, 3>>& tris) {
  const fs::path path = test::temp_dir("affordances") / (name + ".stl");
  std::ofstream out(path);
  out << "solid " << name << "\n";
  for (const auto& t : tris) {
    const Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
    out << "facet normal " << n.x() << " " << n.y() << " " << n.z() << "\nouter loop\n";
    for (const Vector3d& p : t) out << "vertex " << p.x() << " " << p.y() << " " << p.z() << "\n";
    out << "endloop\nendfacet\n";
  }
  out << "endsolid " << name << "\n";
  return path.string();
}

// Unit squares [x, x + 1] x [y, y + 1] at z = 0, two triangles each, facing up.
std::vector<std::array<Vector3d, 3>> unit_squares(const std::vector<std::pair<int, int>>& cells) {
  std::vector<std::array<Vector3d, 3>> tris;
  for (const auto& [x, y] : cells) {
    const Vector3d a(x, y, 0), b(x + 1, y, 0), c(x + 1, y + 1, 0), d(x, y + 1, 0);
    tris.push_back({a, b, c});
    tris.push_back({a, c, d});
  }
  return tris;
}

std::vector<Affordance> of_kind(const std::vector<Affordance>& all, AffordanceClass kind) {
  std::vector<Affordance> out;
  for (const Affordance& a : all)
    if (a.kind == kind) out.push_back(a);
  return out;
}

// Is p (link frame, on the plane z = 0) inside one of the surfaces?
bool covered(const std::vector<Affordance>& surfaces, const Vector3d& p_L) {
  for (const Affordance& a : surfaces) {
    const Vector3d p_S = a.surface.T_LS.inverse() * p_L;
    if (distance_outside(a.surface.vertices_S, p_S.head<2>()) <= 1e-9) return true;
  }
  return false;
}

TEST(Affordances, ABoxGivesItsTopAsSupportAndItsSidesAsLean) {
  const Model model = one_link("<box size=\"1 0.8 0.5\"/>", "0 0 0.25");
  const std::vector<Affordance> found = extract_affordances(model, Eigen::Isometry3d::Identity());
  ASSERT_EQ(found.size(), 5u);  // the bottom faces down: dropped
  const Affordance& top = found[0];
  EXPECT_EQ(top.surface.name, "support_0");
  EXPECT_EQ(top.kind, AffordanceClass::Support);
  EXPECT_EQ(top.surface.link_name, "body");
  EXPECT_NEAR((top.surface.normal_L() - Vector3d::UnitZ()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(top.surface.area(), 0.8, 1e-12);
  ASSERT_EQ(top.surface.vertices_S.size(), 4u);
  for (const Vector3d& v : top.surface.vertices_L()) {
    EXPECT_NEAR(v.z(), 0.5, 1e-12);
    EXPECT_NEAR(std::abs(v.x()), 0.5, 1e-12);
    EXPECT_NEAR(std::abs(v.y()), 0.4, 1e-12);
  }
  // Leans at one height, ordered by x then y: -x, -y, +y, +x.
  const Vector3d normals[] = {-Vector3d::UnitX(), -Vector3d::UnitY(), Vector3d::UnitY(),
                              Vector3d::UnitX()};
  const double areas[] = {0.4, 0.5, 0.5, 0.4};
  for (int i = 0; i < 4; ++i) {
    const Affordance& side = found[1 + i];
    EXPECT_EQ(side.surface.name, "lean_" + std::to_string(i));
    EXPECT_EQ(side.kind, AffordanceClass::Lean);
    EXPECT_NEAR((side.normal_W - normals[i]).norm(), 0.0, 1e-12) << side.surface.name;
    EXPECT_NEAR(side.surface.area(), areas[i], 1e-12) << side.surface.name;
  }
}

TEST(Affordances, TheBasePoseDecidesWhatIsUpAndTheOrder) {
  const Model model = one_link("<box size=\"1 0.8 0.5\"/>");
  // Rolled a quarter turn about x: the box's +y face now faces up.
  Eigen::Isometry3d T_WB = Eigen::Isometry3d::Identity();
  T_WB.linear() = Eigen::AngleAxisd(M_PI / 2, Vector3d::UnitX()).toRotationMatrix();
  const std::vector<Affordance> found = extract_affordances(model, T_WB);
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found[0].surface.name, "support_0");
  EXPECT_NEAR((found[0].surface.normal_L() - Vector3d::UnitY()).norm(), 0.0, 1e-12);
  EXPECT_NEAR(found[0].centroid_W.z(), 0.4, 1e-12);
  EXPECT_NEAR(found[0].surface.area(), 0.5, 1e-12);
}

TEST(Affordances, AnLShapedFloorMeshGivesTwoConvexSupportsCoveringIt) {
  const std::string stl = write_stl("l_floor", unit_squares({{0, 0}, {1, 0}, {0, 1}}));
  const Model model = one_link("<mesh filename=\"" + stl + "\"/>");
  const std::vector<Affordance> found = extract_affordances(model, Eigen::Isometry3d::Identity());
  ASSERT_EQ(found.size(), 2u);
  double area = 0.0;
  for (const Affordance& a : found) {
    EXPECT_EQ(a.kind, AffordanceClass::Support);
    EXPECT_EQ(a.surface.vertices_S.size(), 4u) << a.surface.name;  // two rectangles
    area += a.surface.area();
  }
  EXPECT_NEAR(area, 3.0, 1e-12);  // no overlap, nothing missing
  for (double x = 0.05; x < 2.0; x += 0.1)
    for (double y = 0.05; y < 2.0; y += 0.1)
      if (x < 1.0 || y < 1.0) {
        EXPECT_TRUE(covered(found, Vector3d(x, y, 0))) << x << " " << y;
      }
}

TEST(Affordances, AFloorAroundAHoleIsCoveredByConvexPieces) {
  std::vector<std::pair<int, int>> cells;
  for (int x = 0; x < 3; ++x)
    for (int y = 0; y < 3; ++y)
      if (x != 1 || y != 1) cells.emplace_back(x, y);
  const std::string stl = write_stl("ring_floor", unit_squares(cells));
  const Model model = one_link("<mesh filename=\"" + stl + "\"/>");
  const std::vector<Affordance> found = extract_affordances(model, Eigen::Isometry3d::Identity());
  ASSERT_GE(found.size(), 4u);  // at least four around a hole
  ASSERT_LE(found.size(), 5u);  // four reflex corners: at most 4 + 1
  double area = 0.0;
  for (const Affordance& a : found) area += a.surface.area();
  EXPECT_NEAR(area, 8.0, 1e-9);
  EXPECT_FALSE(covered(found, Vector3d(1.5, 1.5, 0)));
  for (double x = 0.05; x < 3.0; x += 0.1)
    for (double y = 0.05; y < 3.0; y += 0.1)
      if (std::abs(x - 1.5) > 0.5 || std::abs(y - 1.5) > 0.5) {
        EXPECT_TRUE(covered(found, Vector3d(x, y, 0))) << x << " " << y;
      }
}

TEST(Affordances, A45DegreeRampIsNoSupportUnderA30DegreeSlope) {
  const Model model = one_link("<box size=\"2 1 0.1\"/>", "0 0 0.5", "0 0.785398163397 0");
  const std::vector<Affordance> found = extract_affordances(model, Eigen::Isometry3d::Identity());
  EXPECT_TRUE(of_kind(found, AffordanceClass::Support).empty());
  // Only its two vertical ends (+y, -y) are lean; the 45-degree faces are neither.
  ASSERT_EQ(of_kind(found, AffordanceClass::Lean).size(), 2u);
  AffordanceOptions steep;
  steep.slope = 50.0;
  const std::vector<Affordance> with_50 =
      extract_affordances(model, Eigen::Isometry3d::Identity(), steep);
  // With 50 degrees: its top and its upper end (1 x 0.1 m), both 45 degrees from up.
  const std::vector<Affordance> supports = of_kind(with_50, AffordanceClass::Support);
  ASSERT_EQ(supports.size(), 2u);
  for (const Affordance& a : supports) EXPECT_NEAR(a.normal_W.z(), std::sqrt(0.5), 1e-9);
  EXPECT_NEAR(supports[0].surface.area() + supports[1].surface.area(), 2.1, 1e-9);
}

TEST(Affordances, ACylinderGivesItsTopCapAsAnInscribedPolygon) {
  const Model model = one_link("<cylinder radius=\"0.3\" length=\"0.4\"/>", "0 0 0.2");
  const std::vector<Affordance> found = extract_affordances(model, Eigen::Isometry3d::Identity());
  ASSERT_EQ(found.size(), 1u);  // the curved side gives nothing, the bottom faces down
  EXPECT_EQ(found[0].surface.name, "support_0");
  EXPECT_EQ(found[0].surface.vertices_S.size(), 32u);
  EXPECT_NEAR(found[0].surface.area(), 16.0 * 0.09 * std::sin(2.0 * M_PI / 32.0), 1e-12);
  EXPECT_NEAR(found[0].centroid_W.z(), 0.4, 1e-12);
}

TEST(Affordances, InsetAndMinAreaShrinkAndDrop) {
  const Model model = one_link("<box size=\"1 0.8 0.5\"/>", "0 0 0.25");
  AffordanceOptions options;
  options.inset = 0.1;
  options.min_area = 0.25;  // the sides shrink to 0.8 x 0.3 and 0.6 x 0.3: dropped
  const std::vector<Affordance> found =
      extract_affordances(model, Eigen::Isometry3d::Identity(), options);
  ASSERT_EQ(found.size(), 1u);
  EXPECT_NEAR(found[0].surface.area(), 0.8 * 0.6, 1e-12);
}

TEST(Affordances, NamesFollowHeightThenXThenYAndRepeat) {
  const Model model =
      load_urdf(test::source_path("assets/environments/stairs/stairs.urdf"), UrdfOptions{});
  const std::vector<Affordance> first = extract_affordances(model, Eigen::Isometry3d::Identity());
  const std::vector<Affordance> second = extract_affordances(model, Eigen::Isometry3d::Identity());
  ASSERT_EQ(first.size(), second.size());
  for (size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].surface.name, second[i].surface.name);
    EXPECT_EQ(first[i].surface.link_name, second[i].surface.link_name);
    EXPECT_EQ(first[i].surface.vertices_S, second[i].surface.vertices_S);
  }
  const std::vector<Affordance> supports = of_kind(first, AffordanceClass::Support);
  ASSERT_EQ(supports.size(), 6u);  // the floor and five treads
  EXPECT_EQ(supports[0].surface.link_name, "floor");
  for (int k = 1; k <= 5; ++k) {
    EXPECT_EQ(supports[k].surface.name, "support_" + std::to_string(k));
    EXPECT_EQ(supports[k].surface.link_name, "step_" + std::to_string(k));
    EXPECT_NEAR(supports[k].centroid_W.z(), 0.1 * k, 1e-12);
  }
}

// Two triangles 0.1 m across sharing the edge (0,0,0)-(0.1,0,0); the second bent about it by
// `angle` (rad), or lifted at its far vertex by `lift` (m).
std::vector<PlanarRegion> bent_pair(double angle, double lift, const PlanarRegionOptions& o) {
  const std::vector<Vector3d> vertices = {
      {0, 0, 0},
      {0.1, 0, 0},
      {0.05, 0.1, 0},
      {0.05, -0.1 * std::cos(angle), 0.1 * std::sin(angle) + lift}};
  const std::vector<Eigen::Vector3i> triangles = {{0, 1, 2}, {1, 0, 3}};
  return find_planar_regions(vertices, triangles, o);
}

TEST(Affordances, CoplanarMergeHonoursBothTolerances) {
  const double degree = M_PI / 180.0;
  PlanarRegionOptions o;
  o.offset_tolerance = 1.0;                               // angles only
  EXPECT_EQ(bent_pair(1.9 * degree, 0.0, o).size(), 1u);  // default: 2 degrees
  EXPECT_EQ(bent_pair(2.1 * degree, 0.0, o).size(), 2u);
  o.angle_tolerance = 0.5 * degree;
  EXPECT_EQ(bent_pair(1.0 * degree, 0.0, o).size(), 2u);
  // Offsets only: 4 mm above the plane is within the default 5 mm, not within 3 mm.
  o = PlanarRegionOptions{};
  o.angle_tolerance = 10.0 * degree;
  EXPECT_EQ(bent_pair(0.0, 0.0049, o).size(), 1u);
  EXPECT_EQ(bent_pair(0.0, 0.0051, o).size(), 2u);
  o.offset_tolerance = 0.003;
  EXPECT_EQ(bent_pair(0.0, 0.004, o).size(), 2u);
  // Merged: one region, its outline one quadrilateral, its area both triangles'.
  const std::vector<PlanarRegion> merged = bent_pair(1.0 * degree, 0.0, PlanarRegionOptions{});
  ASSERT_EQ(merged.size(), 1u);
  ASSERT_EQ(merged[0].outlines.size(), 1u);
  EXPECT_EQ(merged[0].outlines[0].outer.size(), 4u);
  EXPECT_NEAR(merged[0].area, 0.01, 1e-12);
}

}  // namespace
}  // namespace stanceplan
