// OrbitCamera: taking over a framed camera, orbit, pan (the scene follows the cursor) and zoom.
#include "app/gui/orbit_camera.h"

#include <gtest/gtest.h>

#include <cmath>

namespace stanceplan::gui {
namespace {

// Pixel position of a world point in a view of the given size (y down, as on screen).
Eigen::Vector2d project(const render::Camera& camera, const Eigen::Vector3d& p_W, double w,
                        double h) {
  const Eigen::Vector4d clip =
      camera.projection_matrix(w / h, 0.1, 100.0) * camera.view_matrix() * p_W.homogeneous();
  const Eigen::Vector2d ndc = clip.head<2>() / clip.w();
  return {(ndc.x() + 1.0) * 0.5 * w, (1.0 - ndc.y()) * 0.5 * h};
}

render::Camera framed() {
  render::Camera c;
  c.eye = Eigen::Vector3d(3.0, -4.0, 2.0);
  c.target = Eigen::Vector3d(0.5, 0.2, 0.8);
  c.fov_y_deg = 35.0;
  return c;
}

TEST(OrbitCamera, TakesOverAFramedCameraUnchanged) {
  const render::Camera c = OrbitCamera(framed()).camera();
  EXPECT_LT((c.eye - framed().eye).norm(), 1e-12);
  EXPECT_LT((c.target - framed().target).norm(), 1e-12);
  EXPECT_EQ(c.fov_y_deg, 35.0);
}

TEST(OrbitCamera, OrbitKeepsTheTargetAndTheDistance) {
  OrbitCamera camera(framed());
  const double d = camera.distance();
  const double azimuth = camera.azimuth(), elevation = camera.elevation();
  camera.orbit(100.0, -50.0);
  const render::Camera c = camera.camera();
  EXPECT_LT((c.target - framed().target).norm(), 1e-12);
  EXPECT_NEAR((c.eye - c.target).norm(), d, 1e-12);
  EXPECT_NEAR(camera.azimuth(), azimuth - 100.0 * OrbitCamera::kRadiansPerPixel, 1e-12);
  EXPECT_NEAR(camera.elevation(), elevation - 50.0 * OrbitCamera::kRadiansPerPixel, 1e-12);
}

TEST(OrbitCamera, ElevationStopsShortOfThePoles) {
  OrbitCamera camera(framed());
  camera.orbit(0.0, 1e6);
  EXPECT_EQ(camera.elevation(), OrbitCamera::kMaxElevation);
  camera.orbit(0.0, -1e7);
  EXPECT_EQ(camera.elevation(), -OrbitCamera::kMaxElevation);
}

// Dragging by (dx, dy) moves what was under the cursor at the target's depth by (dx, dy).
TEST(OrbitCamera, PanMovesTheSceneWithTheCursor) {
  const double w = 800.0, h = 600.0;
  OrbitCamera camera(framed());
  const Eigen::Vector3d p_W = framed().target;
  const Eigen::Vector2d before = project(camera.camera(), p_W, w, h);
  camera.pan(40.0, -25.0, h);
  const Eigen::Vector2d after = project(camera.camera(), p_W, w, h);
  EXPECT_NEAR(after.x() - before.x(), 40.0, 1e-6);
  EXPECT_NEAR(after.y() - before.y(), -25.0, 1e-6);
}

TEST(OrbitCamera, ZoomScalesTheDistanceWithinLimits) {
  OrbitCamera camera(framed());
  const double d = camera.distance();
  camera.zoom(2.0);
  EXPECT_NEAR(camera.distance(), d * 0.81, 1e-12);
  camera.zoom(-2.0);
  EXPECT_NEAR(camera.distance(), d, 1e-12);
  camera.zoom(1000.0);
  EXPECT_EQ(camera.distance(), OrbitCamera::kMinDistance);
}

}  // namespace
}  // namespace stanceplan::gui
