#pragma once
// Triangle meshes from files (STL, DAE, OBJ, ... anything assimp reads), flattened into one vertex
// and triangle list in the mesh file's frame, scaled. The one mesh loader of the project: the
// collision hulls take its vertices (planner/collision/collision_model.h), the renderer its
// triangles and colours (render/scene/mesh_file.h adds the normals). Independent of FCL and GL.
#include <Eigen/Core>
#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace stanceplan {

struct TriangleMesh {
  // In the file's order: nodes depth first (a node's meshes before its children), each mesh's
  // vertices in assimp's order. The hulls, and so the plans, depend on this order.
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;  // counter-clockwise seen from outside (outward normals)
  // Empty when no mesh of the file has a material colour (an STL file only gets assimp's
  // placeholder material); otherwise one RGBA per vertex: the file's own vertex colour when its
  // mesh has one, else the diffuse colour of its mesh's material (alpha times opacity), grey
  // (179, 179, 179, 255) for a mesh without one.
  std::vector<std::array<std::uint8_t, 4>> colors;
  // The meshes whose material has a diffuse texture file: their vertices (`num_vertices` from
  // `first_vertex`) and the texture's path as the file names it, resolved against the mesh file's
  // folder. The planner decodes no image: the renderer multiplies their colours by the texture's
  // mean colour (render/scene/mesh_file.h). Textures embedded in the file are not listed.
  struct TexturedPart {
    int first_vertex = 0;
    int num_vertices = 0;
    std::string texture_path;
  };
  std::vector<TexturedPart> textured_parts;
};

// Loads every triangle of the file: the scene graph is flattened (each node's transform applied to
// the meshes it references, including a COLLADA file's unit; its up_axis is ignored, as ROS tools
// do, so a Z_UP file keeps its authored axes), then every vertex is
// multiplied component-wise by `scale`. A mirroring transform or scale (negative determinant) would
// turn the triangles inside out; their winding is reversed so that normals stay outward.
// Throws InputError "mesh file \"PATH\" ...: <reason>" when the file is missing, unreadable or has
// no triangles. Vertices are not checked: see require_finite_vertices.
TriangleMesh load_mesh(const std::string& path,
                       const Eigen::Vector3d& scale = Eigen::Vector3d::Ones());

// A NaN or infinite vertex (a corrupt file) would poison a hull and every distance after it: throws
// InputError "mesh file \"PATH\": vertex I is not finite (X Y Z)" for the first one. The collision
// hulls require this; the renderer draws what it is given.
void require_finite_vertices(const TriangleMesh& mesh, const std::string& path);

}  // namespace stanceplan
