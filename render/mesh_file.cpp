#include "render/mesh_file.h"

#include <assimp/config.h>
#include <assimp/material.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <assimp/Importer.hpp>
#include <cstdint>

#include "planner/util/input_error.h"

namespace stanceplan::render {
namespace {

struct Flattened {
  std::vector<Eigen::Vector3f> positions;
  std::vector<std::uint32_t> indices;
  std::vector<std::array<std::uint8_t, 4>> colors;
  bool any_material_color = false;
};

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
bool material_color(const aiScene& scene, const aiMesh& mesh, std::array<std::uint8_t, 4>* rgba) {
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

void append_mesh(const aiScene& scene, const aiMesh& mesh, const Eigen::Matrix4d& T_FN,
                 const Eigen::Vector3d& scale, Flattened* out) {
  std::array<std::uint8_t, 4> rgba = {179, 179, 179, 255};
  out->any_material_color |= material_color(scene, mesh, &rgba);
  const auto first = static_cast<std::uint32_t>(out->positions.size());
  for (unsigned i = 0; i < mesh.mNumVertices; ++i) {
    const aiVector3D& v = mesh.mVertices[i];
    const Eigen::Vector4d p_F = T_FN * Eigen::Vector4d(v.x, v.y, v.z, 1.0);
    out->positions.push_back(p_F.head<3>().cwiseProduct(scale).cast<float>());
    out->colors.push_back(rgba);
  }
  // A mirror (negative determinant) turns every triangle inside out: swap two corners back.
  const bool mirrored = T_FN.topLeftCorner<3, 3>().determinant() * scale.prod() < 0.0;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;  // points and lines have no surface to draw
    const std::uint32_t a = first + face.mIndices[0], b = first + face.mIndices[1],
                        c = first + face.mIndices[2];
    if (mirrored)
      out->indices.insert(out->indices.end(), {a, c, b});
    else
      out->indices.insert(out->indices.end(), {a, b, c});
  }
}

void append_node(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& T_FP,
                 const Eigen::Vector3d& scale, Flattened* out) {
  const Eigen::Matrix4d T_FN = T_FP * to_eigen(node.mTransformation);
  for (unsigned i = 0; i < node.mNumMeshes; ++i)
    append_mesh(scene, *scene.mMeshes[node.mMeshes[i]], T_FN, scale, out);
  for (unsigned i = 0; i < node.mNumChildren; ++i)
    append_node(scene, *node.mChildren[i], T_FN, scale, out);
}

}  // namespace

LoadedMesh load_mesh_file(const std::string& path, const Eigen::Vector3d& scale) {
  Assimp::Importer importer;
  importer.SetPropertyBool(AI_CONFIG_IMPORT_COLLADA_IGNORE_UP_DIRECTION, true);
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr)
    throw InputError("mesh file \"" + path + "\" could not be read: " + importer.GetErrorString());
  Flattened flat;
  append_node(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), scale, &flat);
  if (flat.indices.empty()) throw InputError("mesh file \"" + path + "\" has no triangles");
  LoadedMesh out;
  out.has_material_colors = flat.any_material_color;
  if (!out.has_material_colors) flat.colors.clear();
  out.mesh = with_crease_normals(flat.positions, flat.indices, flat.colors);
  return out;
}

}  // namespace stanceplan::render
