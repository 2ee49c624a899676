// Surface files' fields: each surface is given by exactly one of vertices, box_face and face, with
// only the keys of its kind (anything else is refused with its line, as in scenario files);
// x_axis with box_face; `face:` as an axis name or a vector; the project's own surface files load.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "planner/contact/surface_file.h"
#include "planner/model/urdf_loader.h"
#include "planner/util/input_error.h"
#include "tests/support/paths.h"
#include "tests/support/test_models.h"

#include "tests/support/surface_file_fixture.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;

class SurfaceFileFields : public test::SurfaceFileTest {};

TEST_F(SurfaceFileFields, UnknownKeysAreRefusedWithTheirLine) {
  EXPECT_EQ(error_of("  - name: sole\n"
                     "    link: foot\n"
                     "    normal: [0, 0, -1]\n"
                     "    vertices: [[0, 0, -0.1], [0, -0.1, -0.1], [0.1, 0, -0.1]]\n"
                     "    x_axsi: [1, 0, 0]\n"),
            path_ +
                ":7: surfaces[0].x_axsi: unknown field (expected one of: name, link, normal, "
                "vertices, x_axis)");
  EXPECT_EQ(error_of("  - {name: a, link: base, box_face: +z}\n"
                     "  - {name: b, link: base, box_face: -z, normal: [0, 0, -1]}\n"),
            path_ +
                ":4: surfaces[1].normal: not a field of a box_face surface (expected one of: "
                "name, link, box_face, box_index, inset, x_axis)");
  EXPECT_EQ(error_of("  - name: sole\n    link: foot\n    face: -z\n    box_index: 1\n"),
            path_ +
                ":6: surfaces[0].box_index: not a field of a face surface (expected one of: "
                "name, link, face, inset, x_axis)");
  EXPECT_EQ(error_of("  - {name: a, link: base, box_face: +z, face: +z}\n"),
            path_ +
                ":3: surfaces[0]: give one of vertices, box_face, face or point, found "
                "box_face and face");
  std::ofstream(path_) << "format: stanceplan/surfaces@1\nsurface:\n  - {name: a}\n";
  try {
    load_surface_file(path_, model_);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              path_ + ":2: surface: unknown field (expected one of: format, surfaces)");
  }
}

TEST_F(SurfaceFileFields, XAxisWithBoxFaceMeansWhatItMeansWithVertices) {
  const std::vector<Surface> s = load(
      "  - {name: default, link: base, box_face: -z}\n"
      "  - {name: given, link: base, box_face: -z, x_axis: [1, 0, 0.3]}\n"
      "  - {name: polygon, link: base, normal: [0, 0, -1], x_axis: [1, 0, 0.3],\n"
      "     vertices: [[0.1, 0.15, 0.15], [0.1, -0.15, 0.15], [-0.1, -0.15, 0.15],\n"
      "                [-0.1, 0.15, 0.15]]}\n");
  ASSERT_EQ(s.size(), 3u);
  // Without x_axis, box_face keeps its box's first axis in the face: the box's y, the link's -x.
  EXPECT_TRUE(s[0].T_LS.linear().col(0).isApprox(Eigen::Vector3d(-1, 0, 0), 1e-12));
  // With it, the given axis projected on the face, as for the same polygon given by vertices.
  EXPECT_TRUE(s[1].T_LS.linear().col(0).isApprox(Eigen::Vector3d(1, 0, 0), 1e-12));
  EXPECT_TRUE(s[1].T_LS.isApprox(s[2].T_LS, 1e-12));
  EXPECT_EQ(s[1].vertices_L().size(), 4u);
  for (int i = 0; i < 4; ++i) EXPECT_TRUE(s[1].vertex_L(i).isApprox(s[0].vertex_L(i), 1e-12));
  EXPECT_EQ(
      error_of("  - {name: a, link: base, box_face: -z, x_axis: [0, 0, 2]}\n"),
      path_ + ":3: surface \"a\": face -z of link \"base\": x_axis is parallel to the normal");
}

TEST_F(SurfaceFileFields, FaceIsAnAxisNameOrADirection) {
  const std::vector<Surface> s = load(
      "  - {name: named, link: foot, face: -z, inset: 0.005}\n"
      "  - {name: vector, link: foot, face: [0, 0.1, -2], inset: 0.005}\n");
  ASSERT_EQ(s.size(), 2u);
  EXPECT_TRUE(s[0].T_LS.isApprox(s[1].T_LS, 1e-12));
  EXPECT_NEAR(s[0].area(), s[1].area(), 1e-12);
  EXPECT_EQ(error_of("  - {name: a, link: foot, face: down}\n"),
            path_ +
                ":3: surface \"a\": face: expected one of +x -x +y -y +z -z or a direction [x, "
                "y, z], found \"down\"");
  EXPECT_EQ(error_of("  - {name: a, link: foot, face: [0, 0, 0]}\n"),
            path_ + ":3: surface \"a\": face: the direction [0, 0, 0] has no sense");
  EXPECT_EQ(error_of("  - {name: a, link: foot, face: -z, inset: -0.01}\n"),
            path_ + ":3: surface \"a\": inset: expected a margin >= 0 (m), found -0.01");
  EXPECT_EQ(error_of("  - {name: a, link: ball, face: [0, 0, -1]}\n"),
            path_ +
                ":3: surface \"a\": link \"ball\" has no flat face: its collision geometry "
                "is sphere of radius 0.05 m");
}

// Every surface file of the project (assets/, tests/data/) still loads with its model: none holds
// a key the reader used to ignore.
TEST(ProjectSurfaceFiles, EveryOneLoadsWithItsModel) {
  int checked = 0;
  for (const char* root : {"assets", "tests/data"}) {
    for (const auto& entry :
         std::filesystem::recursive_directory_iterator(test::source_path(root))) {
      const std::string path = entry.path().string();
      const std::string suffix = ".surfaces.yaml";
      if (path.size() < suffix.size() ||
          path.compare(path.size() - suffix.size(), suffix.size(), suffix) != 0)
        continue;
      const std::filesystem::path urdf =
          entry.path().parent_path() /
          (entry.path().filename().string().substr(
               0, entry.path().filename().string().size() - suffix.size()) +
           ".urdf");
      if (!std::filesystem::exists(urdf)) continue;  // a model outside the repository (TALOS)
      const Model model = load_urdf(urdf.string());
      EXPECT_NO_THROW(load_surface_file(path, model)) << path;
      ++checked;
    }
  }
  EXPECT_GE(checked, 15);
}

}  // namespace
}  // namespace stanceplan
