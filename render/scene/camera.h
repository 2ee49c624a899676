#pragma once
// A pinhole camera (eye, target, up, vertical field of view) and automatic framing. Named views
// look at the scene from fixed directions (x forward, y left, z up); frame_box() places the eye
// so that a bounding box fills the picture. Compute the framing once and reuse it for every image
// of a sequence so that the frames line up.
#include <Eigen/Geometry>
#include <optional>
#include <string>
#include <string_view>

namespace stanceplan::render {

enum class View { Front, Side, Top, ThreeQuarter };

// "front" | "side" | "top" | "three-quarter"; nullopt otherwise.
std::optional<View> parse_view(std::string_view text);
const char* to_string(View view);
// Unit direction from the target towards the eye, and the up vector, of a named view.
Eigen::Vector3d view_direction(View view);
Eigen::Vector3d view_up(View view);

struct Camera {
  Eigen::Vector3d eye = Eigen::Vector3d(4.0, -4.0, 2.5);
  Eigen::Vector3d target = Eigen::Vector3d(0.0, 0.0, 0.8);
  Eigen::Vector3d up = Eigen::Vector3d::UnitZ();
  double fov_y_deg = 30.0;

  // World to camera (OpenGL convention: the camera looks down its -z axis).
  Eigen::Matrix4d view_matrix() const;
  // Perspective projection for an image of the given aspect (width / height).
  Eigen::Matrix4d projection_matrix(double aspect, double near, double far) const;
};

// Free space around the framed box, as fractions of the image: `side` on every side, plus `top`
// and `bottom` (room for a caption and a legend).
struct FrameMargins {
  double side = 0.05;
  double top = 0.0;
  double bottom = 0.0;
};

// The camera looking along the named view that frames `box` in an image of `aspect`.
Camera frame_box(const Eigen::AlignedBox3d& box, View view, double aspect,
                 const FrameMargins& margins = {}, double fov_y_deg = 30.0);
// Same, for an explicit direction (target towards eye) and up vector.
Camera frame_box(const Eigen::AlignedBox3d& box, const Eigen::Vector3d& direction,
                 const Eigen::Vector3d& up, double aspect, const FrameMargins& margins,
                 double fov_y_deg);

}  // namespace stanceplan::render
