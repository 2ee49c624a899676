#include "render/scene/camera.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace stanceplan::render {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// Horizontal views are raised a little so that the ground, the feet and their contacts show.
Eigen::Vector3d from_angles(double azimuth_deg, double elevation_deg) {
  const double a = azimuth_deg * kDeg, e = elevation_deg * kDeg;
  return Eigen::Vector3d(std::cos(a) * std::cos(e), std::sin(a) * std::cos(e), std::sin(e));
}

}  // namespace

std::optional<View> parse_view(std::string_view text) {
  if (text == "front") return View::Front;
  if (text == "side") return View::Side;
  if (text == "top") return View::Top;
  if (text == "three-quarter") return View::ThreeQuarter;
  return std::nullopt;
}

const char* to_string(View view) {
  switch (view) {
    case View::Front:
      return "front";
    case View::Side:
      return "side";
    case View::Top:
      return "top";
    case View::ThreeQuarter:
      return "three-quarter";
  }
  return "?";
}

Eigen::Vector3d view_direction(View view) {
  switch (view) {
    case View::Front:
      return from_angles(0.0, 12.0);  // facing the robot (it faces +x)
    case View::Side:
      return from_angles(-90.0, 12.0);  // its right side: +x runs rightwards
    case View::Top:
      return Eigen::Vector3d::UnitZ();
    case View::ThreeQuarter:
      return from_angles(-52.0, 22.0);  // front right, from above
  }
  return Eigen::Vector3d::UnitX();
}

Eigen::Vector3d view_up(View view) {
  return view == View::Top ? Eigen::Vector3d::UnitY() : Eigen::Vector3d::UnitZ();
}

Eigen::Matrix4d Camera::view_matrix() const {
  const Eigen::Vector3d f = (target - eye).normalized();
  const Eigen::Vector3d r = f.cross(up).normalized();
  const Eigen::Vector3d u = r.cross(f);
  Eigen::Matrix4d m = Eigen::Matrix4d::Identity();
  m.block<1, 3>(0, 0) = r.transpose();
  m.block<1, 3>(1, 0) = u.transpose();
  m.block<1, 3>(2, 0) = -f.transpose();
  m(0, 3) = -r.dot(eye);
  m(1, 3) = -u.dot(eye);
  m(2, 3) = f.dot(eye);
  return m;
}

Eigen::Matrix4d Camera::projection_matrix(double aspect, double near, double far) const {
  const double t = 1.0 / std::tan(0.5 * fov_y_deg * kDeg);
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  m(0, 0) = t / aspect;
  m(1, 1) = t;
  m(2, 2) = (far + near) / (near - far);
  m(2, 3) = 2.0 * far * near / (near - far);
  m(3, 2) = -1.0;
  return m;
}

Camera frame_box(const Eigen::AlignedBox3d& box, View view, double aspect,
                 const FrameMargins& margins, double fov_y_deg) {
  return frame_box(box, view_direction(view), view_up(view), aspect, margins, fov_y_deg);
}

Camera frame_box(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& direction,
                 const Eigen::Vector3d& up, double aspect, const FrameMargins& margins,
                 double fov_y_deg) {
  const Eigen::Vector3d f = -direction.normalized();
  const Eigen::Vector3d right = f.cross(up).normalized();
  const Eigen::Vector3d cam_up = right.cross(f);
  const double ty = std::tan(0.5 * fov_y_deg * kDeg), tx = ty * aspect;
  // The usable window in normalised device coordinates: [-hx, hx] x [cy - hy, cy + hy].
  const double hx = 1.0 - 2.0 * margins.side;
  const double hy = 1.0 - 2.0 * margins.side - margins.top - margins.bottom;
  const double cy = margins.bottom - margins.top;
  Eigen::Vector3d corners[8];
  for (int i = 0; i < 8; ++i)
    corners[i] = box.corner(static_cast<Eigen::AlignedBox3d::CornerType>(i));

  // Start from a symmetric fit around the box centre (always fits), then re-centre the projected
  // box in the window and scale the distance to make it just fill it: a few fixed-point steps.
  Eigen::Vector3d target = box.center();
  double distance = 1e-3;
  for (const Eigen::Vector3d& c : corners) {
    const Eigen::Vector3d rel = c - target;
    distance = std::max({distance, std::abs(rel.dot(right)) / (hx * tx) - rel.dot(f),
                         std::abs(rel.dot(cam_up)) / (hy * ty) - rel.dot(f)});
  }
  // Perspective makes each step approximate: iterate to the fixed point (a handful of steps).
  for (int iteration = 0; iteration < 50; ++iteration) {
    const Eigen::Vector3d eye = target - distance * f;
    double min_x = 1e9, max_x = -1e9, min_y = 1e9, max_y = -1e9;
    for (const Eigen::Vector3d& c : corners) {
      const Eigen::Vector3d rel = c - eye;
      const double depth = std::max(rel.dot(f), 1e-6);
      min_x = std::min(min_x, rel.dot(right) / depth / tx);
      max_x = std::max(max_x, rel.dot(right) / depth / tx);
      min_y = std::min(min_y, rel.dot(cam_up) / depth / ty);
      max_y = std::max(max_y, rel.dot(cam_up) / depth / ty);
    }
    const double centre_depth = (box.center() - eye).dot(f);
    const double shift_x = 0.5 * (min_x + max_x), shift_y = 0.5 * (min_y + max_y) - cy;
    const double k = std::max((max_x - min_x) / (2.0 * hx), (max_y - min_y) / (2.0 * hy));
    if (std::abs(shift_x) < 1e-5 && std::abs(shift_y) < 1e-5 && std::abs(k - 1.0) < 1e-5) break;
    target += right * (shift_x * tx * centre_depth) + cam_up * (shift_y * ty * centre_depth);
    distance = std::max(distance + centre_depth * (k - 1.0), 1e-3);
  }
  Camera camera;
  camera.target = target;
  camera.eye = target - distance * f;
  camera.up = cam_up;
  camera.fov_y_deg = fov_y_deg;
  return camera;
}

}  // namespace stanceplan::render
