// The off-screen renderer on known scenes: pixel facts, depth order, determinism, a real robot.
// Runs with no display at all (OSMesa).
#include <gtest/gtest.h>

#include "app/pipeline.h"
#include "planner/io/plan_reader.h"
#include "planner/model/urdf_loader.h"
#include "render/figures/sequence.h"
#include "render/renderer.h"
#include "tests/render/render_fixtures.h"

namespace stanceplan::render {
namespace {

const Eigen::Vector4d kRed(1.0, 0.0, 0.0, 1.0);
const Eigen::Vector4d kBlue(0.0, 0.0, 1.0, 1.0);

bool is_rgb(const Image& image, int x, int y, int r, int g, int b) {
  const std::uint8_t* p = image.pixel(x, y);
  return p[0] == r && p[1] == g && p[2] == b;
}

int count_rgb(const Image& image, int r, int g, int b) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += is_rgb(image, x, y, r, g, b) ? 1 : 0;
  return n;
}

TEST(Renderer, UnitBoxCoversTheExpectedPixelsAndNothingElse) {
  const Scene scene = test::boxes_scene({{Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), kRed}});
  Renderer renderer(200, 200, test::plain_style());
  const Image image = renderer.render(scene, Eigen::VectorXd(0), {}, {}, test::camera_on_x_axis());
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  ASSERT_EQ(image.rgba.size(), 200u * 200u * 4u);
  // The front face (x = 0.5, 4.5 m away) spans tan-1(0.5 / 4.5) / tan(15 deg) = 0.415 of the
  // half-height: 41.5 px around the centre.
  EXPECT_TRUE(is_rgb(image, 100, 100, 255, 0, 0));
  EXPECT_TRUE(is_rgb(image, 100 + 38, 100 - 38, 255, 0, 0));
  EXPECT_TRUE(is_rgb(image, 100 + 46, 100, 255, 255, 255));
  EXPECT_TRUE(is_rgb(image, 100, 100 + 46, 255, 255, 255));
  EXPECT_TRUE(is_rgb(image, 2, 2, 255, 255, 255));
  EXPECT_TRUE(is_rgb(image, 197, 197, 255, 255, 255));
  const double expected = 83.0 * 83.0;
  EXPECT_NEAR(count_rgb(image, 255, 0, 0), expected, 0.06 * expected);
  // Every pixel is box, background, or an anti-aliased mix of the two along the edges.
  EXPECT_NEAR(count_rgb(image, 255, 0, 0) + count_rgb(image, 255, 255, 255), 200 * 200, 4 * 83 * 2);
}

TEST(Renderer, ImageRowsAreTopDown) {
  // A box above the target must appear in the upper half of the image.
  const Scene scene =
      test::boxes_scene({{Eigen::Vector3d(0, 0, 0.8), Eigen::Vector3d(0.4, 0.4, 0.4), kRed}});
  Renderer renderer(120, 120, test::plain_style());
  const Image image = renderer.render(scene, Eigen::VectorXd(0), {}, {}, test::camera_on_x_axis());
  EXPECT_TRUE(is_rgb(image, 60, 20, 255, 0, 0));
  EXPECT_TRUE(is_rgb(image, 60, 100, 255, 255, 255));
}

TEST(Renderer, NearBoxHidesFarBoxWhateverTheDrawingOrder) {
  const test::TestBox near{Eigen::Vector3d(1.0, 0.0, 0.0), Eigen::Vector3d::Constant(0.5), kRed};
  const test::TestBox far{Eigen::Vector3d(-2.0, 0.0, 0.0), Eigen::Vector3d::Constant(2.0), kBlue};
  Renderer renderer(200, 200, test::plain_style());
  for (const auto& boxes :
       {std::vector<test::TestBox>{near, far}, std::vector<test::TestBox>{far, near}}) {
    const Image image = renderer.render(test::boxes_scene(boxes), Eigen::VectorXd(0), {}, {},
                                        test::camera_on_x_axis());
    // Near box: +-25 px around the centre; far box: +-62 px.
    EXPECT_TRUE(is_rgb(image, 100, 100, 255, 0, 0));
    EXPECT_TRUE(is_rgb(image, 100 + 20, 100 + 20, 255, 0, 0));
    EXPECT_TRUE(is_rgb(image, 100 + 45, 100, 0, 0, 255));
    EXPECT_TRUE(is_rgb(image, 100, 100 - 45, 0, 0, 255));
    EXPECT_TRUE(is_rgb(image, 100 + 75, 100, 255, 255, 255));
  }
}

TEST(Renderer, SameInputsGiveIdenticalPixels) {
  const std::string dir = test::fresh_dir("determinism");
  const LoadedPlan plan = read_plan(test::write_humanoid_plan(dir, 3), {.build_collision = false});
  SequenceOptions options;
  options.width = 320;
  options.height = 240;
  SequenceRenderer first(app::plan_view(plan), options);
  const Image a = first.render_step(1);
  const Image b = first.render_step(1);
  SequenceRenderer second(app::plan_view(plan), options);
  const Image c = second.render_step(1);
  EXPECT_TRUE(a == b);
  EXPECT_TRUE(a == c);
  EXPECT_FALSE(a == first.render_step(2));  // and the picture does depend on the step
}

TEST(Renderer, TalosWithMirroredStlMeshesFillsAPlausibleSilhouette) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  Eigen::VectorXd q;
  const Scene scene = test::talos_scene(&q);
  RenderStyle style = test::plain_style();
  style.lighting = true;  // meshes must render lit; the background stays exactly white
  style.center_of_mass = false;
  Renderer renderer(240, 320, style);
  const Image image = renderer.render(scene, q, {}, {}, renderer.frame(scene, q, {}, View::Front));
  EXPECT_TRUE(renderer.take_warnings().empty());
  int robot = 0, left = 0, right = 0, top = image.height, bottom = -1;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      if (is_rgb(image, x, y, 255, 255, 255)) continue;
      ++robot;
      (x < image.width / 2 ? left : right) += 1;
      top = std::min(top, y);
      bottom = std::max(bottom, y);
    }
  }
  const double share = static_cast<double>(robot) / (image.width * image.height);
  EXPECT_GT(share, 0.10);
  EXPECT_LT(share, 0.60);
  // Framed: the robot spans most of the height, inside the margins.
  EXPECT_GT(bottom - top, 0.8 * image.height);
  EXPECT_GT(top, 0);
  EXPECT_LT(bottom, image.height - 1);
  // Seen from the front the robot is left-right symmetric: the mirrored meshes (scale 1 -1 1)
  // must land where their counterparts' mirror images are.
  EXPECT_NEAR(static_cast<double>(left) / right, 1.0, 0.08);
}

TEST(Renderer, CollisionGeometryOnRequest) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  Eigen::VectorXd q;
  const Scene scene = test::talos_scene(&q);
  RenderStyle style = test::plain_style();
  style.collision_geometry = true;
  style.center_of_mass = false;
  Renderer renderer(160, 200, style);
  const Image image = renderer.render(scene, q, {}, {}, renderer.frame(scene, q, {}, View::Front));
  EXPECT_TRUE(renderer.take_warnings().empty());
  const int background = count_rgb(image, 255, 255, 255);
  EXPECT_GT(image.width * image.height - background, image.width * image.height / 10);
}

TEST(Renderer, DaeMeshesKeepTheirMaterialColours) {
  STANCEPLAN_REQUIRE_SHARED("robots/panda");
  // The Panda's visual meshes are COLLADA files with white and dark grey materials and no URDF
  // colour: flat shading must show both, not the default grey.
  UrdfOptions options;
  options.packages.directories = {test::panda_package_dir()};
  options.packages.use_ros_package_path = false;
  Entity entity;
  entity.name = "panda";
  entity.kind = EntityKind::FixedRobot;
  entity.model = std::make_shared<const Model>(load_urdf(test::panda_urdf(), options));
  Scene scene;
  scene.system.add(entity);
  scene.surfaces = SurfaceSet(1);
  const Eigen::VectorXd q = scene.system.neutral_configuration();
  RenderStyle style = test::plain_style();
  style.background_bottom = Color{0.0f, 0.4f, 0.0f, 1.0f};  // a colour no material has
  Renderer renderer(200, 200, style);
  const Image image =
      renderer.render(scene, q, {}, {}, renderer.frame(scene, q, {}, View::ThreeQuarter));
  EXPECT_TRUE(renderer.take_warnings().empty());
  int light = 0, dark = 0, default_grey = 0;
  const std::uint8_t* grey = nullptr;
  const Image probe(1, 1, style.default_color);
  grey = probe.pixel(0, 0);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] == 0 && p[2] == 0) continue;  // background
      light += p[0] > 200 && p[1] > 200 && p[2] > 200 ? 1 : 0;
      dark += p[0] < 90 && p[1] < 90 && p[2] < 90 ? 1 : 0;
      default_grey += p[0] == grey[0] && p[1] == grey[1] && p[2] == grey[2] ? 1 : 0;
    }
  }
  EXPECT_GT(light, 500);
  EXPECT_GT(dark, 50);
  EXPECT_EQ(default_grey, 0);
}

TEST(Renderer, RejectsAConfigurationOfTheWrongSize) {
  const Scene scene = test::boxes_scene({{Eigen::Vector3d::Zero(), Eigen::Vector3d::Ones(), kRed}});
  Renderer renderer(64, 64, test::plain_style());
  EXPECT_THROW(renderer.render(scene, Eigen::VectorXd::Zero(3), {}, {}, test::camera_on_x_axis()),
               std::invalid_argument);
}

}  // namespace
}  // namespace stanceplan::render
