// Mesh loading (assimp: STL, OBJ, DAE with its scene graph; scale and mirroring) and convex hulls
// (qhull: containment, orientation, closed surface, degenerate input).
#include <fcl/geometry/shape/convex.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "planner/collision/convex_hull.h"
#include "planner/model/mesh_file.h"
#include "planner/util/input_error.h"
#include "tests/planner/collision/collision_test_scene.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

std::string talos_mesh(const std::string& relative) {
  return test::shared_path("robots/talos/robots/talos_data/meshes/" + relative);
}

std::vector<std::string> talos_collision_meshes() {
  std::vector<std::string> paths;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(talos_mesh(""))) {
    const std::string name = entry.path().filename().string();
    if (name.find("_collision.") != std::string::npos) paths.push_back(entry.path().string());
  }
  std::sort(paths.begin(), paths.end());
  return paths;
}

// Sum of signed tetrahedron volumes: positive when the triangles face outward.
double signed_volume(const std::vector<Eigen::Vector3d>& v,
                     const std::vector<Eigen::Vector3i>& triangles) {
  double six_volume = 0.0;
  for (const Eigen::Vector3i& t : triangles) six_volume += v[t[0]].dot(v[t[1]].cross(v[t[2]]));
  return six_volume / 6.0;
}

// Every point inside every face plane (within tol); every non-degenerate triangle wound like its
// plane's outward normal; every edge shared by exactly two triangles, in opposite directions.
void expect_valid_hull(const ConvexHull& hull, const std::vector<Eigen::Vector3d>& points,
                       double tol) {
  ASSERT_EQ(hull.triangles.size(), hull.planes.size());
  ASSERT_GE(hull.vertices.size(), 4u);
  double worst = -1.0;
  for (const Eigen::Vector4d& plane : hull.planes) {
    EXPECT_NEAR(plane.head<3>().norm(), 1.0, 1e-12);
    for (const Eigen::Vector3d& p : points) {
      worst = std::max(worst, plane.head<3>().dot(p) + plane[3]);
    }
  }
  EXPECT_LE(worst, tol) << "a point lies outside the hull";
  std::map<std::pair<int, int>, int> directed_edges;
  for (size_t f = 0; f < hull.triangles.size(); ++f) {
    const Eigen::Vector3i& t = hull.triangles[f];
    const Eigen::Vector3d& a = hull.vertices[t[0]];
    const Eigen::Vector3d cross = (hull.vertices[t[1]] - a).cross(hull.vertices[t[2]] - a);
    if (cross.norm() > 1e-12) {
      EXPECT_GT(cross.dot(hull.planes[f].head<3>()), 0.0);
    }
    for (int k = 0; k < 3; ++k) ++directed_edges[{t[k], t[(k + 1) % 3]}];
  }
  for (const auto& [edge, count] : directed_edges) {
    EXPECT_EQ(count, 1);
    EXPECT_EQ(directed_edges.count({edge.second, edge.first}), 1u) << "open edge";
  }
  EXPECT_GT(signed_volume(hull.vertices, hull.triangles), 0.0);
}

TEST(MeshLoader, EveryTalosCollisionMeshLoadsAndHulls) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const std::vector<std::string> paths = talos_collision_meshes();
  ASSERT_GE(paths.size(), 20u);
  for (const std::string& path : paths) {
    SCOPED_TRACE(path);
    const TriangleMesh mesh = load_mesh(path);
    EXPECT_GT(mesh.triangles.size(), 3u);
    EXPECT_GT(signed_volume(mesh.vertices, mesh.triangles), 0.0);
    const ConvexHull hull = convex_hull(mesh.vertices);
    expect_valid_hull(hull, mesh.vertices, 1e-9);
    // FCL accepts it as a closed convex mesh (it throws on open or disconnected meshes).
    auto vertices = std::make_shared<std::vector<Eigen::Vector3d>>(hull.vertices);
    auto faces = std::make_shared<std::vector<int>>();
    for (const Eigen::Vector3i& t : hull.triangles)
      faces->insert(faces->end(), {3, t[0], t[1], t[2]});
    EXPECT_NO_THROW(fcl::Convexd(vertices, static_cast<int>(hull.triangles.size()), faces, true));
  }
}

TEST(ConvexHull, SimplifiedHullGrownByItsMarginContainsTheMesh) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  for (const char* relative : {"arm/arm_3_collision.STL", "torso/base_link_collision.STL"}) {
    SCOPED_TRACE(relative);
    const TriangleMesh mesh = load_mesh(talos_mesh(relative));
    const ConvexHull exact = convex_hull(mesh.vertices);
    ConvexHullOptions options;
    options.simplify_tolerance = 1e-3;
    const ConvexHull simple = convex_hull(mesh.vertices, options);
    EXPECT_LT(simple.vertices.size(), 0.6 * exact.vertices.size());
    EXPECT_LT(exact.max_outside_distance, 1e-12);
    EXPECT_GT(simple.max_outside_distance, 0.0);
    EXPECT_LT(simple.max_outside_distance, 3e-3);
    // A plane's violation never exceeds the Euclidean distance to the hull.
    expect_valid_hull(simple, mesh.vertices, simple.max_outside_distance + 1e-12);
  }
}

TEST(MeshLoader, MirroredMeshKeepsOutwardWindingAndMirrorsTheHull) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  const std::string path = talos_mesh("v2/knee_collision.stl");
  const TriangleMesh plain = load_mesh(path);
  const TriangleMesh mirrored = load_mesh(path, Eigen::Vector3d(1, -1, 1));
  ASSERT_EQ(plain.vertices.size(), mirrored.vertices.size());
  for (size_t i = 0; i < plain.vertices.size(); ++i) {
    EXPECT_EQ(mirrored.vertices[i], Eigen::Vector3d(plain.vertices[i].x(), -plain.vertices[i].y(),
                                                    plain.vertices[i].z()));
  }
  const double volume = signed_volume(plain.vertices, plain.triangles);
  EXPECT_GT(volume, 0.0);
  EXPECT_NEAR(signed_volume(mirrored.vertices, mirrored.triangles), volume, 1e-12);

  const ConvexHull hull = convex_hull(plain.vertices);
  const ConvexHull mirrored_hull = convex_hull(mirrored.vertices);
  expect_valid_hull(mirrored_hull, mirrored.vertices, 1e-9);
  auto sorted = [](std::vector<Eigen::Vector3d> v) {
    std::sort(v.begin(), v.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
      return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
    });
    return v;
  };
  std::vector<Eigen::Vector3d> mirrored_back = mirrored_hull.vertices;
  for (Eigen::Vector3d& v : mirrored_back) v.y() = -v.y();
  EXPECT_EQ(sorted(mirrored_back), sorted(hull.vertices));
}

TEST(MeshLoader, ScaleAppliesPerAxis) {
  const std::string obj = test::write_octahedron_obj();
  const TriangleMesh mesh = load_mesh(obj, Eigen::Vector3d(2.0, 3.0, -0.5));
  ASSERT_EQ(mesh.vertices.size(), 6u);
  ASSERT_EQ(mesh.triangles.size(), 8u);
  // assimp stores single-precision floats.
  EXPECT_LT((mesh.vertices[0] - Eigen::Vector3d(0.1, 0.009, 0.0)).norm(), 1e-7);
  EXPECT_GT(signed_volume(mesh.vertices, mesh.triangles), 0.0);  // mirrored by the -0.5
}

TEST(MeshLoader, ColladaSceneGraphIsFlattened) {
  STANCEPLAN_REQUIRE_SHARED("robots/panda");
  // The Panda's visual DAE files carry node transforms (and a unit); once flattened they must
  // cover the same region as the collision STL of the same link.
  const std::string dir = test::shared_path("robots/panda/robots/panda_description/meshes/");
  for (const char* link : {"link0", "link3", "link7", "hand"}) {
    SCOPED_TRACE(link);
    const TriangleMesh visual = load_mesh(dir + "visual/" + link + ".dae");
    const TriangleMesh collision = load_mesh(dir + "collision/" + link + ".stl");
    Eigen::AlignedBox3d box_visual, box_collision;
    for (const auto& p : visual.vertices) box_visual.extend(p);
    for (const auto& p : collision.vertices) box_collision.extend(p);
    EXPECT_LT((box_visual.min() - box_collision.min()).cwiseAbs().maxCoeff(), 0.02);
    EXPECT_LT((box_visual.max() - box_collision.max()).cwiseAbs().maxCoeff(), 0.02);
  }
}

TEST(MeshLoader, MissingFileIsAnInputErrorNamingThePath) {
  const std::string path = "/nonexistent/dir/missing_mesh.stl";
  try {
    load_mesh(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("\"" + path + "\""), std::string::npos) << e.what();
  }
}

TEST(MeshLoader, UnreadableFileIsAnInputErrorNamingThePath) {
  const std::filesystem::path path = test::temp_dir("collision") / "garbage.stl";
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << "this is not a mesh\n";
  try {
    load_mesh(path.string());
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path.string()), std::string::npos) << e.what();
  }
}

TEST(ConvexHull, CubeWithInteriorPoints) {
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < 8; ++i) points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  points.emplace_back(0.5, 0.5, 0.5);
  points.emplace_back(0.2, 0.7, 0.1);
  points.emplace_back(0.5, 0.5, 1.0);  // on a face
  const ConvexHull hull = convex_hull(points);
  EXPECT_EQ(hull.vertices.size(), 8u);
  EXPECT_EQ(hull.triangles.size(), 12u);
  expect_valid_hull(hull, points, 1e-12);
  EXPECT_NEAR(signed_volume(hull.vertices, hull.triangles), 1.0, 1e-12);
}

TEST(ConvexHull, FlatInputIsThickenedOrRejected) {
  // A 0.2 x 0.1 rectangle in the tilted plane z = x: no 3-D hull.
  std::vector<Eigen::Vector3d> plate = {
      {0, 0, 0}, {0.2, 0, 0.2}, {0.2, 0.1, 0.2}, {0, 0.1, 0}, {0.1, 0.05, 0.1}};
  const ConvexHull slab = convex_hull(plate);
  expect_valid_hull(slab, plate, 1e-12);
  EXPECT_NEAR(signed_volume(slab.vertices, slab.triangles),
              std::sqrt(0.08) * 0.1 * ConvexHullOptions().degenerate_thickness, 1e-12);
  ConvexHullOptions strict;
  strict.degenerate_thickness = 0.0;
  EXPECT_THROW(convex_hull(plate, strict), std::invalid_argument);
  // Collinear points become a thin prism; a single repeated point has no hull.
  const std::vector<Eigen::Vector3d> line = {{0, 0, 0}, {0.1, 0.1, 0.1}, {0.3, 0.3, 0.3}};
  expect_valid_hull(convex_hull(line), line, 1e-12);
  EXPECT_THROW(convex_hull({{1, 2, 3}, {1, 2, 3}}), std::invalid_argument);
  EXPECT_THROW(convex_hull({}), std::invalid_argument);
}

}  // namespace
}  // namespace stanceplan
