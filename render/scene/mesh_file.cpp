#include "render/scene/mesh_file.h"

#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <vector>

#include "planner/model/mesh_file.h"
#include "render/image/texture_color.h"

namespace stanceplan::render {
namespace {

using Rgba = std::array<std::uint8_t, 4>;

// Multiplies the colours of every textured part by its texture's mean colour (each texture file
// decoded once); a texture that cannot be read leaves the part's diffuse colour and a warning.
void apply_texture_means(const TriangleMesh& file, const std::string& path,
                         std::vector<Rgba>* colors, std::vector<std::string>* warnings) {
  std::map<std::string, std::array<float, 3>> means;
  for (const TriangleMesh::TexturedPart& part : file.textured_parts) {
    auto it = means.find(part.texture_path);
    if (it == means.end()) {
      try {
        it = means.emplace(part.texture_path, mean_texture_color(part.texture_path)).first;
      } catch (const std::runtime_error& e) {
        warnings->push_back("mesh file \"" + path + "\": " + e.what() +
                            " (its material's diffuse colour is used)");
        means.emplace(part.texture_path, std::array<float, 3>{1.0f, 1.0f, 1.0f});
        continue;
      }
    }
    for (int v = part.first_vertex; v < part.first_vertex + part.num_vertices; ++v) {
      Rgba& c = (*colors)[static_cast<size_t>(v)];
      for (int k = 0; k < 3; ++k)
        c[k] = static_cast<std::uint8_t>(std::lround(c[k] * it->second[k]));
    }
  }
}

}  // namespace

LoadedMesh load_mesh_file(const std::string& path, const Eigen::Vector3d& scale) {
  const TriangleMesh file = stanceplan::load_mesh(path, scale);
  std::vector<Eigen::Vector3f> positions;
  positions.reserve(file.vertices.size());
  for (const Eigen::Vector3d& p : file.vertices) positions.push_back(p.cast<float>());
  std::vector<std::uint32_t> indices;
  indices.reserve(3 * file.triangles.size());
  for (const Eigen::Vector3i& t : file.triangles) {
    indices.insert(indices.end(),
                   {static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]),
                    static_cast<std::uint32_t>(t[2])});
  }
  LoadedMesh out;
  out.has_material_colors = !file.colors.empty();
  std::vector<Rgba> colors = file.colors;
  if (!colors.empty()) apply_texture_means(file, path, &colors, &out.warnings);
  out.mesh = with_crease_normals(positions, indices, colors);
  return out;
}

}  // namespace stanceplan::render
