#pragma once
// Visual meshes from files, ready to draw: the triangles and material colours of the project's one
// mesh loader (planner/model/mesh_file.h: assimp, scene graph flattened, COLLADA unit kept, up-axis
// ignored as ROS tools do, scaled, a mirroring scale keeping outward winding), with crease-angle
// normals added. A texture-mapped material is drawn in its diffuse colour times the texture's mean
// colour (no texture mapping: docs/RENDERING.md).
#include <Eigen/Core>
#include <string>
#include <vector>

#include "render/scene/mesh_data.h"

namespace stanceplan::render {

struct LoadedMesh {
  MeshData mesh;  // crease-angle normals; colours set only when has_material_colors
  // The file's own colours (materials, vertex colours, textures): drawn instead of the URDF's
  // <material>, as rviz does; false for STL files, whose visuals take the URDF's colour.
  bool has_material_colors = false;
  // Faults that leave the mesh drawable (a texture that cannot be read: its material's diffuse
  // colour is used), each naming the file.
  std::vector<std::string> warnings;
};

// Throws InputError naming the file when it is missing, unreadable or holds no triangle.
LoadedMesh load_mesh_file(const std::string& path,
                          const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

}  // namespace stanceplan::render
