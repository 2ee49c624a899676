// Corrupt and empty mesh files: the mesh loader (planner/model/mesh_file.h), as the collision
// hulls use it (with require_finite_vertices) and as the renderer does (render/scene/mesh_file.h),
// ends in an InputError naming the file; a URDF whose collision mesh is corrupt makes
// `stanceplan inspect` exit 1 with the mesh named.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>

#include "planner/model/mesh_file.h"
#include "planner/util/input_error.h"
#include "render/scene/mesh_file.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

std::string write(const std::string& name, const std::string& bytes) {
  const std::string path = (test::temp_dir("mesh_faults") / name).string();
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

// A binary STL: 80-byte header (not starting with "solid"), triangle count, and `written` of the
// `claimed` triangles (50 bytes each).
std::string binary_stl(uint32_t claimed, uint32_t written) {
  std::string bytes(80, 'x');
  bytes.append(reinterpret_cast<const char*>(&claimed), 4);
  bytes.append(std::string(50 * written, '\0'));
  return bytes;
}

const char* kNanStl =
    "solid bad\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex nan 0 0\n   vertex 0 "
    "1 0\n"
    "  endloop\n endfacet\nendsolid bad\n";

std::string collision_error(const std::string& path) {
  try {
    require_finite_vertices(load_mesh(path, Eigen::Vector3d::Ones()), path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string render_error(const std::string& path) {
  try {
    render::load_mesh_file(path, Eigen::Vector3d::Ones());
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(MeshFaults, EmptyAndTruncatedFilesNameTheFile) {
  for (const auto& [name, bytes] : std::vector<std::pair<std::string, std::string>>{
           {"empty.stl", ""},
           {"empty.obj", ""},
           {"empty.dae", ""},
           {"truncated.stl", binary_stl(1000, 3)},
           {"garbage.stl", std::string(300, '\x7f')},
           {"garbage.obj", "v 1 2\nf 1 2 9\nthis is no mesh\n"},
           {"no_triangles.stl", binary_stl(0, 0)}}) {
    const std::string path = write(name, bytes);
    EXPECT_THAT(collision_error(path), StartsWith("mesh file \"" + path + "\" ")) << name;
    EXPECT_THAT(render_error(path), StartsWith("mesh file \"" + path + "\" ")) << name;
  }
}

TEST(MeshFaults, ANonFiniteVertexIsRejected) {
  const std::string path = write("nan.stl", kNanStl);
  EXPECT_THAT(collision_error(path),
              StartsWith("mesh file \"" + path + "\": vertex 1 is not finite (nan "));
}

TEST(MeshFaults, ACorruptCollisionMeshMakesInspectExitOne) {
  const std::string mesh = write("corrupt_link.stl", binary_stl(1000, 3));
  const std::string urdf =
      write("corrupt_mesh.urdf",
            "<robot name=\"r\"><link name=\"base\"><collision><geometry><mesh filename=\"" + mesh +
                "\"/></geometry></collision></link></robot>");
  const test::CliResult r = test::run_cli({"inspect", urdf});
  EXPECT_EQ(r.code, 1) << r.out << r.err;
  EXPECT_THAT(r.err, StartsWith("stanceplan: error: "));
  EXPECT_THAT(r.err, HasSubstr(mesh));
  const std::string nan_mesh = write("nan_link.stl", kNanStl);
  const std::string nan_urdf =
      write("nan_mesh.urdf",
            "<robot name=\"r\"><link name=\"base\"><collision><geometry><mesh filename=\"" +
                nan_mesh + "\"/></geometry></collision></link></robot>");
  const test::CliResult nan = test::run_cli({"inspect", nan_urdf});
  EXPECT_EQ(nan.code, 1) << nan.out << nan.err;
  EXPECT_THAT(nan.err, HasSubstr("mesh file \"" + nan_mesh + "\": vertex 1 is not finite"));
}

}  // namespace
}  // namespace stanceplan
