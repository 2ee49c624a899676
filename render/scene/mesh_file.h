#pragma once
// Visual meshes from files, ready to draw: the triangles and material colours of the project's one
// mesh loader (planner/model/mesh_file.h: assimp, scene graph flattened, COLLADA unit kept, up-axis
// ignored as ROS tools do, scaled, a mirroring scale keeping outward winding), with crease-angle
// normals added.
#include <Eigen/Core>
#include <string>

#include "render/scene/mesh_data.h"

namespace stanceplan::render {

struct LoadedMesh {
  MeshData mesh;  // crease-angle normals; colours set only when has_material_colors
  bool has_material_colors = false;
};

// Throws InputError naming the file when it is missing, unreadable or holds no triangle.
LoadedMesh load_mesh_file(const std::string& path,
                          const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

}  // namespace stanceplan::render
