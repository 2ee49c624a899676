#include "app/gui/orbit_camera.h"

#include <algorithm>
#include <cmath>

namespace stanceplan::gui {
namespace {

// Unit vector from the target towards the eye.
Eigen::Vector3d eye_direction(double azimuth, double elevation) {
  return {std::cos(elevation) * std::cos(azimuth), std::cos(elevation) * std::sin(azimuth),
          std::sin(elevation)};
}

}  // namespace

OrbitCamera::OrbitCamera(const render::Camera& camera)
    : target_(camera.target), fov_y_deg_(camera.fov_y_deg) {
  const Eigen::Vector3d d = camera.eye - camera.target;
  distance_ = std::clamp(d.norm(), kMinDistance, kMaxDistance);
  azimuth_ = std::atan2(d.y(), d.x());
  elevation_ = std::clamp(std::asin(std::clamp(d.z() / std::max(d.norm(), 1e-12), -1.0, 1.0)),
                          -kMaxElevation, kMaxElevation);
}

void OrbitCamera::orbit(double dx_px, double dy_px) {
  // Dragging right turns the scene to the right, i.e. the eye to the left.
  azimuth_ = std::remainder(azimuth_ - dx_px * kRadiansPerPixel, 2.0 * M_PI);
  elevation_ = std::clamp(elevation_ + dy_px * kRadiansPerPixel, -kMaxElevation, kMaxElevation);
}

void OrbitCamera::pan(double dx_px, double dy_px, double height_px) {
  if (height_px <= 0.0) return;
  // Metres per pixel at the target's depth: the view spans 2 d tan(fov/2) vertically.
  const double m_per_px = 2.0 * distance_ * std::tan(0.5 * fov_y_deg_ * M_PI / 180.0) / height_px;
  const Eigen::Vector3d forward = -eye_direction(azimuth_, elevation_);
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  // The scene follows the cursor: dragging right moves the target (what is seen) left.
  target_ += m_per_px * (-dx_px * right + dy_px * up);
}

void OrbitCamera::zoom(double steps) {
  distance_ = std::clamp(distance_ * std::pow(0.9, steps), kMinDistance, kMaxDistance);
}

render::Camera OrbitCamera::camera() const {
  render::Camera camera;
  camera.target = target_;
  camera.eye = target_ + distance_ * eye_direction(azimuth_, elevation_);
  camera.up = Eigen::Vector3d::UnitZ();
  camera.fov_y_deg = fov_y_deg_;
  return camera;
}

}  // namespace stanceplan::gui
