#pragma once
// Loads every visual mesh file once (per file and scale) and keeps it for the life of the library;
// also holds the unit primitives. Thread-safe: a snapshot thread and a framing computation may
// share one library. Pointers it returns stay valid as long as the library lives.
#include <Eigen/Core>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>
#include <vector>

#include "planner/model/shape.h"
#include "render/scene/mesh_file.h"

namespace stanceplan::render {

class MeshLibrary {
 public:
  // nullptr when the file cannot be loaded: the fault is recorded as a warning (once per file)
  // and the caller skips the geometry, so that a model with a broken mesh still renders. A loaded
  // mesh's own warnings (an unreadable texture) are recorded too.
  const LoadedMesh* file(const std::string& path, const Eigen::Vector3d& scale);
  // The unit mesh of a primitive shape (Box, Cylinder, Sphere); see mesh_data.h for sizes.
  static const MeshData& primitive(ShapeType type);
  static const MeshData& cone();

  // Records a warning once (repeats of the same text are dropped).
  void warn(const std::string& message);
  // Warnings recorded since the last call.
  std::vector<std::string> take_warnings();

 private:
  void record(const std::string& message);  // with mutex_ held; drops repeats

  using Key = std::tuple<std::string, double, double, double>;
  std::mutex mutex_;
  std::map<Key, std::unique_ptr<LoadedMesh>> meshes_;  // null entry: failed to load
  std::vector<std::string> all_warnings_;
  std::vector<std::string> new_warnings_;
};

}  // namespace stanceplan::render
