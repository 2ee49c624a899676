// Meshes for drawing: primitives, files through assimp (mirrored scales), crease-angle normals.
#include <gtest/gtest.h>

#include "planner/util/input_error.h"
#include "render/scene/mesh_data.h"
#include "render/scene/mesh_file.h"
#include "render/scene/mesh_library.h"
#include "tests/render/render_fixtures.h"

namespace stanceplan::render {
namespace {

// Sum over triangles of area x (outward-ness of the face normal): positive for a closed mesh
// whose triangles turn counter-clockwise seen from outside.
double signed_volume(const MeshData& m) {
  double volume = 0.0;
  for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
    const Eigen::Vector3d a = m.positions[m.indices[i]].cast<double>();
    const Eigen::Vector3d b = m.positions[m.indices[i + 1]].cast<double>();
    const Eigen::Vector3d c = m.positions[m.indices[i + 2]].cast<double>();
    volume += a.dot(b.cross(c)) / 6.0;
  }
  return volume;
}

// Vertex normals agree with the faces they belong to.
double worst_normal_disagreement(const MeshData& m) {
  double worst = 1.0;
  for (size_t i = 0; i + 2 < m.indices.size(); i += 3) {
    const Eigen::Vector3f& a = m.positions[m.indices[i]];
    const Eigen::Vector3f face =
        (m.positions[m.indices[i + 1]] - a).cross(m.positions[m.indices[i + 2]] - a);
    if (face.norm() < 1e-9f) continue;
    for (int k = 0; k < 3; ++k)
      worst = std::min(worst, double(face.normalized().dot(m.normals[m.indices[i + k]])));
  }
  return worst;
}

TEST(MeshData, PrimitivesAreClosedOutwardAndUnitSized) {
  EXPECT_NEAR(signed_volume(unit_box()), 1.0, 1e-6);
  EXPECT_NEAR(signed_volume(unit_cylinder(256)), 3.14159265 * 1.0, 1e-3);
  EXPECT_NEAR(signed_volume(unit_sphere(256, 128)), 4.0 / 3.0 * 3.14159265, 2e-3);
  EXPECT_NEAR(signed_volume(unit_cone(256)), 3.14159265 / 3.0, 1e-3);
  for (const MeshData& m : {unit_box(), unit_cylinder(), unit_sphere(), unit_cone()})
    EXPECT_GT(worst_normal_disagreement(m), 0.0);
  EXPECT_TRUE(unit_box().bounds().isApprox(
      Eigen::AlignedBox3f(Eigen::Vector3f::Constant(-0.5f), Eigen::Vector3f::Constant(0.5f))));
}

TEST(MeshData, RingSurroundsThePolygon) {
  const std::vector<Eigen::Vector3f> square = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const MeshData ring = polygon_ring(square, Eigen::Vector3f::UnitZ(), 0.1f);
  const Eigen::AlignedBox3f box = ring.bounds();
  EXPECT_NEAR(box.min().x(), -0.1f, 1e-6f);
  EXPECT_NEAR(box.max().y(), 1.1f, 1e-6f);
  EXPECT_EQ(polygon(square, Eigen::Vector3f::UnitZ()).num_triangles(), 2);
}

TEST(MeshFile, MirroredScaleKeepsTrianglesOutward) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const std::string stl =
      test::shared_path("robots/talos/robots/talos_data/meshes/v2/knee_lo_res.stl");
  const LoadedMesh plain = load_mesh_file(stl);
  const LoadedMesh mirrored = load_mesh_file(stl, Eigen::Vector3d(1.0, -1.0, 1.0));
  EXPECT_FALSE(plain.has_material_colors);  // STL: the URDF's colour applies
  EXPECT_EQ(plain.mesh.num_triangles(), mirrored.mesh.num_triangles());
  EXPECT_NEAR(plain.mesh.bounds().min().y(), -mirrored.mesh.bounds().max().y(), 1e-6);
  // Same enclosed volume, with the same (positive) sign: the winding was reversed with the mirror.
  EXPECT_GT(signed_volume(plain.mesh), 0.0);
  EXPECT_NEAR(signed_volume(mirrored.mesh), signed_volume(plain.mesh),
              1e-6 * std::abs(signed_volume(plain.mesh)) + 1e-12);
  EXPECT_GT(worst_normal_disagreement(mirrored.mesh), 0.0);
  // Corners sharing position and normal share a vertex: far fewer vertices than 3 per triangle.
  EXPECT_LT(plain.mesh.positions.size(), 2u * plain.mesh.num_triangles());
}

TEST(MeshFile, MissingFileIsAnErrorNamingItAndTheLibraryWarnsOnce) {
  try {
    load_mesh_file("/nonexistent/part.stl");
    FAIL() << "expected InputError";
  } catch (const stanceplan::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/part.stl"), std::string::npos);
  }
  MeshLibrary library;
  EXPECT_EQ(library.file("/nonexistent/part.stl", Eigen::Vector3d::Ones()), nullptr);
  EXPECT_EQ(library.file("/nonexistent/part.stl", Eigen::Vector3d::Ones()), nullptr);
  const std::vector<std::string> warnings = library.take_warnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("/nonexistent/part.stl"), std::string::npos);
  EXPECT_TRUE(library.take_warnings().empty());
}

TEST(MeshFile, DaeMaterialsBecomeVertexColours) {
  STANCEPLAN_REQUIRE_SHARED("robots/panda");
  const LoadedMesh link = load_mesh_file(
      test::shared_path("robots/panda/robots/panda_description/meshes/visual/link6.dae"));
  EXPECT_TRUE(link.has_material_colors);
  ASSERT_EQ(link.mesh.colors.size(), link.mesh.positions.size());
  bool varied = false;
  for (const auto& c : link.mesh.colors) varied |= c != link.mesh.colors.front();
  EXPECT_TRUE(varied);  // several materials on one link
}

}  // namespace
}  // namespace stanceplan::render
