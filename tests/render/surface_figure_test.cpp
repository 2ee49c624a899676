// The surface figure of `inspect --png`: each contact surface a patch in its own palette colour,
// named in that colour in the list at the right; points project where the camera says.
#include <gtest/gtest.h>

#include <filesystem>

#include "planner/contact/surface.h"
#include "render/figures/surface_figure.h"
#include "render/image/png_io.h"
#include "render/scene/surface_overlays.h"
#include "tests/render/render_fixtures.h"
#include "tests/support/cli.h"
#include "tests/support/paths.h"

namespace stanceplan::render {
namespace {

constexpr int kW = 320;
constexpr int kH = 240;

TEST(ProjectToPixel, AgreesWithTheRendererAndRefusesPointsBehindTheEye) {
  const Camera camera = test::camera_on_x_axis();
  Eigen::Vector2d pixel;
  ASSERT_TRUE(project_to_pixel(camera, kW, kH, Eigen::Vector3d::Zero(), pixel));
  EXPECT_NEAR(pixel.x(), 0.5 * kW, 1e-9);
  EXPECT_NEAR(pixel.y(), 0.5 * kH, 1e-9);
  // A small red box off the axis: the renderer draws it where the projection says, and nothing
  // at the mirrored pixel.
  const Eigen::Vector3d p_W(0.0, 0.6, 0.3);
  const Scene scene = test::boxes_scene({{p_W, Eigen::Vector3d::Constant(0.1), {1, 0, 0, 1}}});
  Renderer renderer(kW, kH, test::plain_style());
  const Image image = renderer.render(scene, Eigen::VectorXd(0), {}, {}, camera);
  ASSERT_TRUE(project_to_pixel(camera, kW, kH, p_W, pixel));
  EXPECT_LT(pixel.y(), 0.5 * kH);  // above the centre
  const int x = static_cast<int>(pixel.x()), y = static_cast<int>(pixel.y());
  EXPECT_EQ(image.pixel(x, y)[0], 255);
  EXPECT_EQ(image.pixel(x, y)[1], 0);
  EXPECT_EQ(image.pixel(kW - 1 - x, y)[1], 255);  // background
  EXPECT_FALSE(project_to_pixel(camera, kW, kH, Eigen::Vector3d(6.0, 0, 0), pixel));
}

// A grey 2 m x 2 m slab whose top (z = 0) carries two surfaces: a square on the -y half, another
// on the +y half.
Scene slab_with_two_surfaces() {
  Scene scene = test::boxes_scene(
      {{Eigen::Vector3d(0, 0, -0.05), Eigen::Vector3d(2, 2, 0.1), {0.7, 0.7, 0.7, 1}}});
  std::vector<Surface> surfaces(2);
  for (int i = 0; i < 2; ++i) {
    const double y = i == 0 ? -0.5 : 0.5;
    const std::vector<Eigen::Vector3d> square = {
        {-0.4, y - 0.4, 0}, {0.4, y - 0.4, 0}, {0.4, y + 0.4, 0}, {-0.4, y + 0.4, 0}};
    std::string error;
    EXPECT_TRUE(make_surface(i == 0 ? "right" : "left", 0, "base", square, Eigen::Vector3d::UnitZ(),
                             nullptr, &surfaces[i], &error))
        << error;
  }
  scene.surfaces.set(0, surfaces);
  return scene;
}

// Pixels leaning to blue (palette colour 0, 0x1f77b4) and to red (colour 1, 0xd62728): a channel
// ahead of the other by more than 40 levels (the grey slab and the grid are near neutral).
std::array<int, 2> tinted_pixels(const Image& image) {
  std::array<int, 2> n = {0, 0};
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      n[0] += p[2] - p[0] > 40;
      n[1] += p[0] - p[2] > 40;
    }
  return n;
}

TEST(SurfaceFigure, EachSurfaceIsTintedInItsOwnColourAndNamedInTheList) {
  const Scene scene = slab_with_two_surfaces();
  Renderer renderer(kW, kH);
  const Image image = render_surface_figure(renderer, scene, Eigen::VectorXd(0), View::Top, "");
  // Each patch (0.64 m^2 of a 2 m slab filling most of the picture) tints thousands of pixels
  // towards its own colour: blue for surface 0, red for surface 1.
  ASSERT_EQ(surface_color(0).b > surface_color(0).r, true);
  ASSERT_EQ(surface_color(1).r > surface_color(1).b, true);
  const std::array<int, 2> tinted = tinted_pixels(image);
  EXPECT_GT(tinted[0], 2000);
  EXPECT_GT(tinted[1], 2000);
  // Without surfaces nothing is tinted.
  Scene bare = scene;
  bare.surfaces.set(0, {});
  const std::array<int, 2> plain =
      tinted_pixels(render_surface_figure(renderer, bare, Eigen::VectorXd(0), View::Top, ""));
  EXPECT_EQ(plain[0], 0);
  EXPECT_EQ(plain[1], 0);
}

TEST(SurfaceFigure, InspectWritesThePictureOfAModelsSurfaces) {
  const std::string png = test::temp_dir("inspect_surfaces") / "surfaces.png";
  const test::CliResult r =
      test::run_cli({"inspect", test::source_path("assets/environments/stairs/stairs.urdf"),
                     "--kind", "environment", "--surfaces", "auto", "--png", png});
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("wrote " + png), std::string::npos) << r.out;
  const Image image = read_png(png);
  EXPECT_EQ(image.width, 1280);
  EXPECT_EQ(image.height, 720);
  EXPECT_EQ(test::run_cli({"inspect", test::source_path("assets/environments/stairs/stairs.urdf"),
                           "--png", png, "--view", "below"})
                .code,
            1);
}

}  // namespace
}  // namespace stanceplan::render
