#pragma once
// Geometry attached to a link (URDF <visual> / <collision>), in the link frame.
#include <Eigen/Geometry>
#include <string>

namespace stanceplan {

enum class ShapeType { Box, Cylinder, Sphere, Mesh };

struct Shape {
  ShapeType type = ShapeType::Box;
  // Box: full side lengths (x, y, z). Cylinder: (radius, length, 0) along z. Sphere: (radius, 0,
  // 0).
  Eigen::Vector3d size = Eigen::Vector3d::Zero();
  std::string mesh_uri;   // as written in the URDF (mesh only)
  std::string mesh_path;  // resolved file path; empty when it could not be resolved (visuals only)
  Eigen::Vector3d mesh_scale = Eigen::Vector3d::Ones();  // may be negative (mirrored meshes)
};

struct LinkGeometry {
  Shape shape;
  Eigen::Isometry3d T_LG = Eigen::Isometry3d::Identity();  // geometry frame in the link frame
  bool has_color = false;
  Eigen::Vector4d rgba = Eigen::Vector4d(0.7, 0.7, 0.7, 1.0);
};

}  // namespace stanceplan
