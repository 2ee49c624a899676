#include "planner/model/mesh_file.h"

#include <Eigen/LU>

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <assimp/Importer.hpp>
#include <sstream>
#include <string>

#include "planner/util/input_error.h"

namespace stanceplan {
namespace {

using Rgba = std::array<std::uint8_t, 4>;

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
  Eigen::Matrix4d out;
  out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
      m.d4;
  return out;
}

std::uint8_t channel(float v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f);
}

// The diffuse colour of the mesh's material; false for assimp's placeholder material (the only
// one an STL file gets) so that the URDF colour applies instead.
bool material_color(const aiScene& scene, const aiMesh& mesh, Rgba* rgba) {
  if (mesh.mMaterialIndex >= scene.mNumMaterials) return false;
  const aiMaterial& material = *scene.mMaterials[mesh.mMaterialIndex];
  aiString name;
  if (material.Get(AI_MATKEY_NAME, name) == AI_SUCCESS &&
      std::string(name.C_Str()) == AI_DEFAULT_MATERIAL_NAME)
    return false;
  aiColor4D diffuse;
  if (material.Get(AI_MATKEY_COLOR_DIFFUSE, diffuse) != AI_SUCCESS) return false;
  float opacity = 1.0f;
  material.Get(AI_MATKEY_OPACITY, opacity);
  *rgba = {channel(diffuse.r), channel(diffuse.g), channel(diffuse.b),
           channel(diffuse.a * opacity)};
  return true;
}

// The file of the material's diffuse texture, resolved against the mesh file's folder (as ROS
// tools do); empty when there is none or it is embedded in the file ("*0").
std::string diffuse_texture(const aiScene& scene, const aiMesh& mesh, const std::string& folder) {
  if (mesh.mMaterialIndex >= scene.mNumMaterials) return "";
  aiString name;
  if (scene.mMaterials[mesh.mMaterialIndex]->GetTexture(aiTextureType_DIFFUSE, 0, &name) !=
      AI_SUCCESS)
    return "";
  std::string path = name.C_Str();
  std::replace(path.begin(), path.end(), '\\', '/');  // files written on Windows
  if (path.empty() || path[0] == '*') return "";
  return path[0] == '/' ? path : folder + path;
}

// Appends one assimp mesh, placed by T_FN (node frame -> file frame) and then scaled.
void append_mesh(const aiScene& scene, const aiMesh& mesh, const Eigen::Matrix4d& T_FN,
                 const Eigen::Vector3d& scale, const std::string& folder, TriangleMesh* out,
                 bool* any_material_color) {
  Rgba rgba = {179, 179, 179, 255};
  *any_material_color |= material_color(scene, mesh, &rgba);
  const bool vertex_colors = mesh.HasVertexColors(0);  // authored per vertex (PLY, COLLADA)
  *any_material_color |= vertex_colors;
  const int first = static_cast<int>(out->vertices.size());
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    const aiVector3D& v = mesh.mVertices[i];
    const Eigen::Vector4d p_F = T_FN * Eigen::Vector4d(v.x, v.y, v.z, 1.0);
    out->vertices.push_back(p_F.head<3>().cwiseProduct(scale));
    if (vertex_colors) {
      const aiColor4D& c = mesh.mColors[0][i];
      out->colors.push_back({channel(c.r), channel(c.g), channel(c.b), channel(c.a)});
    } else {
      out->colors.push_back(rgba);
    }
  }
  const std::string texture = diffuse_texture(scene, mesh, folder);
  if (!texture.empty()) {
    *any_material_color = true;
    out->textured_parts.push_back({first, static_cast<int>(mesh.mNumVertices), texture});
  }
  // A negative determinant (mirror) reverses the orientation of every triangle.
  const bool mirrored = T_FN.topLeftCorner<3, 3>().determinant() * scale.prod() < 0.0;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines carry no surface
    Eigen::Vector3i t(first + static_cast<int>(face.mIndices[0]),
                      first + static_cast<int>(face.mIndices[1]),
                      first + static_cast<int>(face.mIndices[2]));
    if (mirrored) std::swap(t[1], t[2]);
    out->triangles.push_back(t);
  }
}

void append_node(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& T_FP,
                 const Eigen::Vector3d& scale, const std::string& folder, TriangleMesh* out,
                 bool* any_material_color) {
  const Eigen::Matrix4d T_FN = T_FP * to_eigen(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i) {
    append_mesh(scene, *scene.mMeshes[node.mMeshes[i]], T_FN, scale, folder, out,
                any_material_color);
  }
  for (unsigned i = 0; i < node.mNumChildren; ++i) {
    append_node(scene, *node.mChildren[i], T_FN, scale, folder, out, any_material_color);
  }
}

}  // namespace

TriangleMesh load_mesh(const std::string& path, const Eigen::Vector3d& scale) {
  Assimp::Importer importer;
  // URDF reads a COLLADA file in its authored axes (as ROS tools do): keep its unit scale, but not
  // assimp's rotation of a Z_UP file into assimp's Y-up convention.
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    throw InputError("mesh file \"" + path + "\" could not be read: " + importer.GetErrorString());
  }
  TriangleMesh mesh;
  bool any_material_color = false;
  const size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "" : path.substr(0, slash + 1);
  append_node(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), scale, folder, &mesh,
              &any_material_color);
  if (mesh.triangles.empty()) {
    throw InputError("mesh file \"" + path + "\" has no triangles");
  }
  if (!any_material_color) mesh.colors = std::vector<Rgba>();
  return mesh;
}

void require_finite_vertices(const TriangleMesh& mesh, const std::string& path) {
  for (size_t i = 0; i < mesh.vertices.size(); ++i) {
    if (mesh.vertices[i].allFinite()) continue;
    std::ostringstream v;
    v << mesh.vertices[i].x() << " " << mesh.vertices[i].y() << " " << mesh.vertices[i].z();
    throw InputError("mesh file \"" + path + "\": vertex " + std::to_string(i) +
                     " is not finite (" + v.str() + ")");
  }
}

}  // namespace stanceplan
