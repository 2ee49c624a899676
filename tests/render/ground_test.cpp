// Where the ground is: an environment's floor under the whole subject, else a plane under the
// lowest point of the scene (never hiding an environment below z = 0); the existing scenes keep
// their ground.
#include <gtest/gtest.h>

#include "planner/io/plan_reader.h"
#include "render/renderer.h"
#include "render/scene/ground.h"
#include "render/scene/scene_assembly.h"
#include "tests/render/render_fixtures.h"

namespace stanceplan::render {
namespace {

using Rgba = std::array<std::uint8_t, 4>;

const Eigen::Vector4d kSlabGreen(0.2, 0.6, 0.4, 1.0);  // (51, 153, 102)
const Eigen::Vector4d kRobotRed(0.8, 0.2, 0.2, 1.0);   // (204, 51, 51)
const Rgba kSlab = {51, 153, 102, 255};
const Rgba kFloorYellow = {255, 255, 0, 255};

Ground ground_of(const Scene& scene, const Eigen::VectorXd& q = Eigen::VectorXd(0)) {
  MeshLibrary meshes;
  return assemble_frame(scene, q, {}, {}, RenderStyle(), meshes).ground;
}

TEST(Ground, AWideSlabUnderTheSubjectIsTheFloorWhereverItIs) {
  const Ground ground =
      ground_of(test::slab_scene(Eigen::Vector2d(4.0, 4.0), -0.9, kSlabGreen, kRobotRed));
  EXPECT_TRUE(ground.environment_floor);
  EXPECT_NEAR(ground.z, -0.9, 1e-6);
  const Ground raised =
      ground_of(test::slab_scene(Eigen::Vector2d(4.0, 4.0), 0.7, kSlabGreen, kRobotRed));
  EXPECT_TRUE(raised.environment_floor);
  EXPECT_NEAR(raised.z, 0.7, 1e-6);
}

TEST(Ground, ASlabNarrowerThanTheSubjectAndItsMarginGetsAPlaneUnderIt) {
  // The subject is 0.3 m wide: its footprint grown by 0.5 m is 1.3 m wide.
  const Ground narrow =
      ground_of(test::slab_scene(Eigen::Vector2d(1.2, 4.0), -0.9, kSlabGreen, kRobotRed));
  EXPECT_FALSE(narrow.environment_floor);
  EXPECT_NEAR(narrow.z, -1.0, 1e-6);  // the slab's bottom: the lowest point of the scene
  const Ground wide_enough =
      ground_of(test::slab_scene(Eigen::Vector2d(1.31, 4.0), -0.9, kSlabGreen, kRobotRed));
  EXPECT_TRUE(wide_enough.environment_floor);
}

TEST(Ground, SlabsSideBySideCoverTogetherAndAGapBreaksTheFloor) {
  for (const double gap : {0.0, 0.02}) {
    Scene scene;
    const double half = 1.0 + 0.5 * gap;
    test::add_fixed_entity(scene, "env", EntityKind::Environment,
                           {test::box_geometry(Eigen::Vector3d(-half, 0, -0.05),
                                               Eigen::Vector3d(2, 4, 0.1), kSlabGreen),
                            test::box_geometry(Eigen::Vector3d(half, 0, -0.05),
                                               Eigen::Vector3d(2, 4, 0.1), kSlabGreen)});
    test::add_fixed_entity(scene, "robot", EntityKind::FixedRobot,
                           {test::box_geometry(Eigen::Vector3d(0, 0, 0.3),
                                               Eigen::Vector3d(0.3, 0.3, 0.6), kRobotRed)});
    test::finish_scene(scene);
    const Ground ground = ground_of(scene);
    EXPECT_EQ(ground.environment_floor, gap == 0.0) << gap;
    EXPECT_NEAR(ground.z, gap == 0.0 ? 0.0 : -0.1, 1e-6) << gap;
  }
}

TEST(Ground, GeometryDeeperThanFiveCentimetresIntoTheSlabMakesItNoFloor) {
  for (const double depth : {0.04, 0.2}) {
    Scene scene;
    test::add_fixed_entity(
        scene, "env", EntityKind::Environment,
        {test::box_geometry(Eigen::Vector3d(0, 0, -0.05), Eigen::Vector3d(6, 6, 0.1), kSlabGreen)});
    test::add_fixed_entity(scene, "robot", EntityKind::FixedRobot,
                           {test::box_geometry(Eigen::Vector3d(0, 0, 0.3 - depth),
                                               Eigen::Vector3d(0.3, 0.3, 0.6), kRobotRed)});
    test::finish_scene(scene);
    const Ground ground = ground_of(scene);
    EXPECT_EQ(ground.environment_floor, depth < 0.05) << depth;
    EXPECT_NEAR(ground.z, depth < 0.05 ? 0.0 : -0.2, 1e-6) << depth;
  }
}

TEST(Ground, WithoutAnEnvironmentThePlaneStaysAtZeroUnderGeometryAboveIt) {
  EXPECT_EQ(ground_of(test::boxes_scene(
                          {{Eigen::Vector3d(0, 0, 1.0), Eigen::Vector3d::Ones(), kRobotRed}}))
                .z,
            0.0);
  EXPECT_EQ(ground_of(test::boxes_scene(
                          {{Eigen::Vector3d(0, 0, -1.0), Eigen::Vector3d::Ones(), kRobotRed}}))
                .z,
            -1.5);
}

TEST(Ground, ExistingScenesKeepTheirGround) {
  // The humanoid on flat_ground (an 8 x 6 m floor slab whose top is z = 0): the environment's
  // floor, as before.
  const std::string dir = test::fresh_dir("ground_humanoid");
  const LoadedPlan plan = read_plan(test::write_humanoid_plan(dir, 2), {.build_collision = false});
  const Ground humanoid = ground_of(plan.scene, plan.plan.steps[1].q);
  EXPECT_TRUE(humanoid.environment_floor);
  EXPECT_NEAR(humanoid.z, 0.0, 1e-6);
}

TEST(Ground, TalosAloneStandsOnAPlaneAtItsSoles) {
  STANCEPLAN_REQUIRE_SHARED("robots/talos");
  Eigen::VectorXd q;
  const Ground ground = ground_of(test::talos_scene(&q), q);
  EXPECT_FALSE(ground.environment_floor);
  EXPECT_LE(ground.z, 0.0);
  EXPECT_GT(ground.z, -0.02);
}

// Where a world point lands in the image (near and far planes do not move it).
Eigen::Vector2i pixel_of(const Camera& camera, const Eigen::Vector3d& p_W, int width, int height) {
  const Eigen::Vector4d clip = camera.projection_matrix(double(width) / height, 0.1, 100.0) *
                               camera.view_matrix() * p_W.homogeneous();
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  return Eigen::Vector2i(static_cast<int>(std::floor(0.5 * (ndc.x() + 1.0) * width)),
                         static_cast<int>(std::floor(0.5 * (1.0 - ndc.y()) * height)));
}

Rgba rgb_at(const Image& image, const Eigen::Vector2i& p) {
  const std::uint8_t* c = image.pixel(p.x(), p.y());
  return {c[0], c[1], c[2], 255};
}

int count_rgb(const Image& image, const Rgba& c) {
  int n = 0;
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) n += rgb_at(image, {x, y}) == c ? 1 : 0;
  return n;
}

// Flat colours, and the renderer's ground plane opaque yellow wherever it is drawn.
RenderStyle ground_style() {
  RenderStyle style = test::plain_style();
  style.floor = true;
  style.floor_color = Color{1.0f, 1.0f, 0.0f, 1.0f};
  style.center_of_mass = false;
  return style;
}

Camera camera_above_slab(double top_z) {
  Camera camera;
  camera.eye = Eigen::Vector3d(3.0, 1.0, top_z + 1.8);
  camera.target = Eigen::Vector3d(0.0, 0.0, top_z + 0.2);
  return camera;
}

TEST(Ground, AFloorBelowZeroIsDrawnNotHidden) {
  // The old renderer drew its opaque plane at z = 0, over this floor at -0.9.
  const Scene scene = test::slab_scene(Eigen::Vector2d(4.0, 4.0), -0.9, kSlabGreen, kRobotRed);
  Renderer renderer(320, 240, ground_style());
  const Camera camera = camera_above_slab(-0.9);
  const Image image = renderer.render(scene, Eigen::VectorXd(0), {}, {}, camera);
  for (const Eigen::Vector3d& p_W :
       {Eigen::Vector3d(0.8, 0.0, -0.9), Eigen::Vector3d(-0.8, -0.8, -0.9),
        Eigen::Vector3d(0.5, 1.2, -0.9)})
    EXPECT_EQ(rgb_at(image, pixel_of(camera, p_W, 320, 240)), kSlab) << p_W.transpose();
  EXPECT_EQ(rgb_at(image, pixel_of(camera, Eigen::Vector3d(0.0, 0.0, -0.5), 320, 240)),
            Rgba({204, 51, 51, 255}));
  EXPECT_EQ(count_rgb(image, kFloorYellow), 0);
  EXPECT_GT(count_rgb(image, kSlab), 320 * 240 / 4);
}

TEST(Ground, APlatformBelowZeroStandsOnAVisibleGroundUnderIt) {
  const Scene scene = test::slab_scene(Eigen::Vector2d(0.9, 0.9), -0.9, kSlabGreen, kRobotRed);
  Renderer renderer(320, 240, ground_style());
  const Camera camera = camera_above_slab(-0.9);
  const Image image = renderer.render(scene, Eigen::VectorXd(0), {}, {}, camera);
  EXPECT_EQ(rgb_at(image, pixel_of(camera, Eigen::Vector3d(0.35, -0.3, -0.9), 320, 240)), kSlab);
  // The ground is at the platform's bottom (z = -1.0), around it.
  EXPECT_EQ(rgb_at(image, pixel_of(camera, Eigen::Vector3d(1.2, -0.6, -1.0), 320, 240)),
            kFloorYellow);
  EXPECT_GT(count_rgb(image, kFloorYellow), 320 * 240 / 4);
}

}  // namespace
}  // namespace stanceplan::render
