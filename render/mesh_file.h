#pragma once
// Visual meshes from files through assimp (STL, DAE, OBJ, ...), keeping what the renderer needs and
// the collision loader drops: each sub-mesh's material colour (DAE/OBJ materials). The scene graph
// is flattened the same way as planner/collision/mesh_loader.h (node transforms, COLLADA unit,
// up-axis ignored as ROS tools do), then scaled; a mirroring scale keeps outward winding.
#include <Eigen/Core>
#include <string>

#include "render/mesh_data.h"

namespace stanceplan::render {

struct LoadedMesh {
  MeshData mesh;  // crease-angle normals; colours set only when has_material_colors
  bool has_material_colors = false;
};

// Throws InputError naming the file when it is missing, unreadable or holds no triangle.
LoadedMesh load_mesh_file(const std::string& path,
                          const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

}  // namespace stanceplan::render
