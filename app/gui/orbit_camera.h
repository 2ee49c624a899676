#pragma once
// Mouse control of the 3-D view's camera: orbit around a target (azimuth about the world z axis,
// elevation above the ground plane), pan the target in the image plane, and zoom by moving the
// eye along the line of sight. Plain math over render::Camera; no window, no GL.
#include <Eigen/Core>

#include "render/scene/camera.h"

namespace stanceplan::gui {

class OrbitCamera {
 public:
  OrbitCamera() = default;
  // Takes over a framed camera (e.g. render::Renderer::frame): same eye, target and field of view.
  explicit OrbitCamera(const render::Camera& camera);

  // Dragging by (dx, dy) pixels: dx turns the azimuth, dy the elevation (clamped short of the
  // poles so that the up vector stays defined).
  void orbit(double dx_px, double dy_px);
  // Dragging by (dx, dy) pixels in a view `height_px` high: the target moves so that the point at
  // the target's depth follows the cursor.
  void pan(double dx_px, double dy_px, double height_px);
  // Mouse wheel: each step moves the eye 10 % closer (positive) or farther (negative).
  void zoom(double steps);

  render::Camera camera() const;
  double distance() const { return distance_; }
  double azimuth() const { return azimuth_; }
  double elevation() const { return elevation_; }
  const Eigen::Vector3d& target() const { return target_; }

  static constexpr double kRadiansPerPixel = 0.008;
  static constexpr double kMaxElevation = 1.5;  // rad, about 86 degrees
  static constexpr double kMinDistance = 0.05;  // m
  static constexpr double kMaxDistance = 500.0;

 private:
  Eigen::Vector3d target_ = Eigen::Vector3d(0.0, 0.0, 0.8);
  double distance_ = 6.0;
  double azimuth_ = -0.785;  // direction target -> eye, measured from +x about +z
  double elevation_ = 0.3;
  double fov_y_deg_ = 30.0;
};

}  // namespace stanceplan::gui
