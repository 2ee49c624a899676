// Models drawn as they are published: a mesh file's own colours (materials, textures) win over
// the URDF's <material>, which colours STL files; TALOS in its authored colours.
#include <gtest/gtest.h>

#include <fstream>
#include <set>

#include "planner/model/urdf_loader.h"
#include "render/image/png_io.h"
#include "render/image/texture_color.h"
#include "render/renderer.h"
#include "render/scene/mesh_file.h"
#include "render/scene/mesh_library.h"
#include "tests/render/render_fixtures.h"

namespace stanceplan::render {
namespace {

using Rgba = std::array<std::uint8_t, 4>;

std::string data(const std::string& name) {
  return test::source_path("tests/data/mesh_materials/" + name);
}

Rgba rgb_at(const Image& image, int x, int y) {
  const std::uint8_t* p = image.pixel(x, y);
  return {p[0], p[1], p[2], 255};
}

int count_rgb(const Image& image, const Rgba& c) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += rgb_at(image, x, y) == c ? 1 : 0;
  return n;
}

Image render_mesh(const LinkGeometry& geometry) {
  Scene scene;
  test::add_fixed_entity(scene, "part", EntityKind::FixedRobot, {geometry});
  test::finish_scene(scene);
  RenderStyle style = test::plain_style();
  style.center_of_mass = false;
  Renderer renderer(200, 200, style);
  const Image image = renderer.render(scene, Eigen::VectorXd(0), {}, {}, test::camera_on_x_axis());
  EXPECT_TRUE(renderer.take_warnings().empty());
  return image;
}

const Rgba kOrange = {204, 102, 51, 255};  // 0.8 0.4 0.2
const Rgba kTeal = {51, 153, 204, 255};    // 0.2 0.6 0.8
const Eigen::Vector4d kUrdfGreen(0.0, 1.0, 0.0, 1.0);
const Rgba kGreen = {0, 255, 0, 255};

TEST(MeshMaterials, DaeDiffuseColoursBecomeVertexColoursPerMesh) {
  const LoadedMesh loaded = load_mesh_file(data("two_materials.dae"));
  ASSERT_TRUE(loaded.has_material_colors);
  ASSERT_EQ(loaded.mesh.colors.size(), loaded.mesh.positions.size());
  for (size_t i = 0; i < loaded.mesh.positions.size(); ++i)
    EXPECT_EQ(loaded.mesh.colors[i], loaded.mesh.positions[i].z() > 0.0f ? kOrange : kTeal) << i;
}

TEST(MeshMaterials, TexturedMaterialTakesTheTexturesMeanColour) {
  const LoadedMesh loaded = load_mesh_file(data("textured.obj"));
  ASSERT_TRUE(loaded.has_material_colors);
  EXPECT_TRUE(loaded.warnings.empty());
  const std::set<Rgba> colors(loaded.mesh.colors.begin(), loaded.mesh.colors.end());
  EXPECT_EQ(colors, std::set<Rgba>({{120, 60, 120, 255}}));  // Kd 1 1 1 times the mean
}

TEST(MeshMaterials, UnreadableTextureKeepsTheDiffuseColourAndWarnsOnce) {
  const std::string dir = test::fresh_dir("missing_texture");
  std::ifstream in(data("textured.obj"));
  std::string obj((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ofstream(dir + "/part.obj") << obj;
  std::ofstream(dir + "/textured.mtl") << "newmtl painted\nKd 0.2 0.6 0.8\nmap_Kd missing.png\n";
  MeshLibrary library;
  const LoadedMesh* loaded = library.file(dir + "/part.obj", Eigen::Vector3d::Ones());
  ASSERT_NE(loaded, nullptr);
  ASSERT_FALSE(loaded->mesh.colors.empty());
  EXPECT_EQ(loaded->mesh.colors.front(), kTeal);
  library.file(dir + "/part.obj", Eigen::Vector3d::Ones());
  const std::vector<std::string> warnings = library.take_warnings();
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_EQ(warnings[0], "mesh file \"" + dir + "/part.obj\": texture \"" + dir +
                             "/missing.png\" could not be read: can't fopen (its material's "
                             "diffuse colour is used)");
}

TEST(MeshMaterials, TextureMeanWeighsPixelsByAlpha) {
  const std::string dir = test::fresh_dir("texture_mean");
  Image image(2, 2, Color{1.0f, 0.0f, 0.0f, 1.0f});  // three opaque red pixels
  image.pixel(1, 1)[0] = 0;
  image.pixel(1, 1)[2] = 255;
  image.pixel(1, 1)[3] = 0;  // and a transparent blue one, which does not count
  write_png(dir + "/t.png", image);
  const std::array<float, 3> mean = mean_texture_color(dir + "/t.png");
  EXPECT_FLOAT_EQ(mean[0], 1.0f);
  EXPECT_FLOAT_EQ(mean[1], 0.0f);
  EXPECT_FLOAT_EQ(mean[2], 0.0f);
  EXPECT_THROW(mean_texture_color(dir + "/none.png"), std::runtime_error);
}

TEST(MeshMaterials, DaeIsDrawnInItsOwnColoursOverTheUrdfColour) {
  // As rviz does: the URDF's green applies only to meshes without materials of their own.
  const Image image = render_mesh(test::mesh_geometry(data("two_materials.dae"), kUrdfGreen));
  EXPECT_EQ(rgb_at(image, 100, 100 - 24), kOrange);
  EXPECT_EQ(rgb_at(image, 100 + 15, 100 - 35), kOrange);
  EXPECT_EQ(rgb_at(image, 100, 100 + 24), kTeal);
  EXPECT_EQ(rgb_at(image, 100 - 15, 100 + 35), kTeal);
  EXPECT_EQ(count_rgb(image, kGreen), 0);
  // Each cube face is about 39 x 39 px.
  EXPECT_NEAR(count_rgb(image, kOrange), 39 * 39, 0.15 * 39 * 39);
  EXPECT_NEAR(count_rgb(image, kTeal), 39 * 39, 0.15 * 39 * 39);
}

TEST(MeshMaterials, TexturedObjIsDrawnInTheTexturesMeanColour) {
  const Image image = render_mesh(test::mesh_geometry(data("textured.obj"), kUrdfGreen));
  EXPECT_EQ(rgb_at(image, 100, 100), Rgba({120, 60, 120, 255}));
  EXPECT_EQ(count_rgb(image, kGreen), 0);
}

TEST(MeshMaterials, StlTakesTheUrdfColourOrTheDefault) {
  const Image green = render_mesh(test::mesh_geometry(data("cube.stl"), kUrdfGreen));
  EXPECT_EQ(rgb_at(green, 100, 100), kGreen);
  const Image plain = render_mesh(test::mesh_geometry(data("cube.stl")));
  const Image probe(1, 1, RenderStyle().default_color);
  EXPECT_EQ(rgb_at(plain, 100, 100), rgb_at(probe, 0, 0));
}

TEST(MeshMaterials, UrdfMaterialWithATextureIsNotDrawnBlack) {
  // urdfdom gives a <material> without <color> the colour (0 0 0 1); with a <texture> (which
  // rviz would draw) the box takes the default grey, not black. A <color> alone still counts.
  const std::string dir = test::fresh_dir("urdf_texture");
  std::ofstream(dir + "/part.urdf") << R"(<robot name="part">
  <material name="painted"><texture filename="stripes.png"/></material>
  <material name="green"><color rgba="0 1 0 1"/></material>
  <link name="base">
    <visual><geometry><box size="0.5 0.5 0.5"/></geometry><material name="painted"/></visual>
    <visual><origin xyz="0 0 1"/><geometry><box size="0.5 0.5 0.5"/></geometry>
      <material name="green"/></visual>
  </link>
</robot>
)";
  const Model model = load_urdf(dir + "/part.urdf");
  ASSERT_EQ(model.links[0].visuals.size(), 2u);
  EXPECT_FALSE(model.links[0].visuals[0].has_color);
  EXPECT_TRUE(model.links[0].visuals[1].has_color);
  const Image image = render_mesh(model.links[0].visuals[0]);
  const Image probe(1, 1, RenderStyle().default_color);
  EXPECT_EQ(rgb_at(image, 100, 100), rgb_at(probe, 0, 0));
}

// TALOS's visuals are STL files coloured by the URDF's named materials (defined at the end of the
// file): grippers Orange (1 0.5 0), torso and head LightGrey (0.9), arms and legs DarkGrey (0.2).
TEST(MeshMaterials, TalosIsDrawnInItsAuthoredColours) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  Eigen::VectorXd q;
  const Scene scene = test::talos_scene(&q);
  RenderStyle style = test::plain_style();
  style.center_of_mass = false;
  Renderer renderer(240, 320, style);
  const Image image = renderer.render(scene, q, {}, {}, renderer.frame(scene, q, {}, View::Front));
  EXPECT_TRUE(renderer.take_warnings().empty());
  int top = image.height, bottom = -1;
  std::vector<Eigen::Vector2i> orange, light, dark;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const Rgba c = rgb_at(image, x, y);
      if (c == Rgba{255, 255, 255, 255}) continue;
      top = std::min(top, y);
      bottom = std::max(bottom, y);
      if (c[0] == 255 && (c[1] == 127 || c[1] == 128) && c[2] == 0) orange.emplace_back(x, y);
      if (c == Rgba{230, 230, 230, 255}) light.emplace_back(x, y);
      if (c == Rgba{51, 51, 51, 255}) dark.emplace_back(x, y);
    }
  }
  ASSERT_GT(bottom, top);
  // Share of the pixels whose height in the robot (0 at the top of its head, 1 under its soles)
  // lies in [from, to].
  const auto share = [&](const std::vector<Eigen::Vector2i>& pixels, double from, double to) {
    int n = 0;
    for (const Eigen::Vector2i& p : pixels) {
      const double h = static_cast<double>(p.y() - top) / (bottom - top);
      n += h >= from && h <= to ? 1 : 0;
    }
    return pixels.empty() ? 0.0 : static_cast<double>(n) / pixels.size();
  };
  // The orange grippers hang at both hands, just under the hips (0.57 to 0.63 of the height).
  EXPECT_GT(orange.size(), 100u);
  EXPECT_EQ(share(orange, 0.5, 0.7), 1.0);
  int left = 0;
  for (const Eigen::Vector2i& p : orange) left += p.x() < image.width / 2 ? 1 : 0;
  EXPECT_GT(left, static_cast<int>(orange.size()) / 3);
  EXPECT_LT(left, 2 * static_cast<int>(orange.size()) / 3);
  // Light grey: head, torso, upper arms and hips, all in the upper 55 %.
  EXPECT_GT(light.size(), 5000u);
  EXPECT_EQ(share(light, 0.0, 0.55), 1.0);
  // Dark grey: shoulders, arms and legs, mostly below the hips.
  EXPECT_GT(dark.size(), 8000u);
  EXPECT_GT(share(dark, 0.5, 1.0), 0.5);
}

}  // namespace
}  // namespace stanceplan::render
