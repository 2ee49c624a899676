#include "render/scene/mesh_library.h"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace stanceplan::render {

const LoadedMesh* MeshLibrary::file(const std::string& path, const Eigen::Vector3d& scale) {
  const Key key{path, scale.x(), scale.y(), scale.z()};
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto it = meshes_.find(key);
    if (it != meshes_.end()) return it->second.get();
  }
  // Load outside the lock: assimp may take a while and other meshes need not wait.
  std::unique_ptr<LoadedMesh> loaded;
  std::string fault;
  try {
    loaded = std::make_unique<LoadedMesh>(load_mesh_file(path, scale));
  } catch (const std::exception& e) {
    fault = e.what();
  }
  std::vector<std::string> messages;
  if (!fault.empty()) messages.push_back(fault + " (visual skipped)");
  if (loaded) messages.insert(messages.end(), loaded->warnings.begin(), loaded->warnings.end());
  std::lock_guard<std::mutex> lock(mutex_);
  auto [it, inserted] = meshes_.emplace(key, std::move(loaded));
  if (inserted) {
    for (const std::string& message : messages) record(message);
  }
  return it->second.get();
}

void MeshLibrary::record(const std::string& message) {
  if (std::find(all_warnings_.begin(), all_warnings_.end(), message) != all_warnings_.end()) return;
  all_warnings_.push_back(message);
  new_warnings_.push_back(message);
}

const MeshData& MeshLibrary::primitive(ShapeType type) {
  static const MeshData box = unit_box();
  static const MeshData cylinder = unit_cylinder();
  static const MeshData sphere = unit_sphere();
  switch (type) {
    case ShapeType::Box:
      return box;
    case ShapeType::Cylinder:
      return cylinder;
    case ShapeType::Sphere:
      return sphere;
    case ShapeType::Mesh:
      break;
  }
  throw std::logic_error("MeshLibrary::primitive: a mesh is not a primitive");
}

const MeshData& MeshLibrary::cone() {
  static const MeshData mesh = unit_cone();
  return mesh;
}

void MeshLibrary::warn(const std::string& message) {
  std::lock_guard<std::mutex> lock(mutex_);
  record(message);
}

std::vector<std::string> MeshLibrary::take_warnings() {
  std::lock_guard<std::mutex> lock(mutex_);
  return std::exchange(new_warnings_, {});
}

}  // namespace stanceplan::render
