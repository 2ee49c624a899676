#pragma once
// Triangle meshes from files (STL, DAE, OBJ, ... anything assimp reads), flattened into one vertex
// and triangle list in the mesh file's frame, scaled. Independent of FCL so that the renderer can
// reuse it.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace stanceplan {

struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;  // counter-clockwise seen from outside (outward normals)
};

// Loads every triangle of the file: the scene graph is flattened (each node's transform applied to
// the meshes it references, including a COLLADA file's unit; its up_axis is ignored, as ROS tools
// do, so a Z_UP file keeps its authored axes), then every vertex is
// multiplied component-wise by `scale`. A mirroring transform or scale (negative determinant) would
// turn the triangles inside out; their winding is reversed so that normals stay outward.
// Throws InputError "mesh file \"PATH\" ...: <reason>" when the file is missing, unreadable or has
// no triangles.
TriangleMesh load_mesh(const std::string& path,
                       const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

}  // namespace stanceplan
