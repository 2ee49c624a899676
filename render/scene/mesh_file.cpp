#include "render/scene/mesh_file.h"

#include <cstdint>
#include <vector>

#include "planner/model/mesh_file.h"

namespace stanceplan::render {

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
  out.mesh = with_crease_normals(positions, indices, file.colors);
  return out;
}

}  // namespace stanceplan::render
