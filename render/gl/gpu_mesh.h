#pragma once
// A MeshData uploaded to GL buffers (one vertex array object). Needs its GL context current.
// Private to render/.
#include "render/scene/mesh_data.h"

namespace stanceplan::render {

class GpuMesh {
 public:
  explicit GpuMesh(const MeshData& mesh);
  ~GpuMesh();
  GpuMesh(const GpuMesh&) = delete;
  GpuMesh& operator=(const GpuMesh&) = delete;

  void draw() const;
  bool has_colors() const { return has_colors_; }

 private:
  unsigned vao_ = 0;
  unsigned vbo_ = 0;
  unsigned ebo_ = 0;
  int count_ = 0;
  bool has_colors_ = false;
};

}  // namespace stanceplan::render
