#pragma once
// Triangle meshes on the CPU, ready for upload: per-vertex positions, normals and (optionally)
// colours, in the geometry's own frame. Independent of GL so that tests and bounds use them.
#include <Eigen/Geometry>
#include <array>
#include <cstdint>
#include <vector>

namespace stanceplan::render {

struct MeshData {
  std::vector<Eigen::Vector3f> positions;
  std::vector<Eigen::Vector3f> normals;
  std::vector<std::array<std::uint8_t, 4>> colors;  // empty, or one RGBA per vertex
  std::vector<std::uint32_t> indices;               // triangles, counter-clockwise from outside

  int num_triangles() const { return static_cast<int>(indices.size() / 3); }
  // The box stored by update_bounds() (every function here calls it); computed when none is.
  Eigen::AlignedBox3f bounds() const;
  void update_bounds();
  // Appends `other` (indices shifted); colours are kept only if both have them or both lack them.
  void append(const MeshData& other);

 private:
  Eigen::AlignedBox3f box_;  // empty until update_bounds(); the renderer asks for it often
};

// Primitive shapes in the URDF conventions, sized 1 so that a scale matrix sizes them.
MeshData unit_box();                                     // side 1, centred
MeshData unit_cylinder(int segments = 48);               // radius 1, length 1 along z, centred
MeshData unit_sphere(int slices = 48, int stacks = 24);  // radius 1
MeshData unit_cone(int segments = 32);  // base radius 1 at z = 0, apex at z = 1, with its base

// A flat convex polygon (counter-clockwise about `normal`), both faces, as a fan.
MeshData polygon(const std::vector<Eigen::Vector3f>& vertices, const Eigen::Vector3f& normal);
// The band between a convex polygon and the polygon grown outward by `width` (both faces).
MeshData polygon_ring(const std::vector<Eigen::Vector3f>& vertices, const Eigen::Vector3f& normal,
                      float width);

// Vertex normals from face normals, averaged only over faces meeting at less than crease_deg
// around each vertex: smooth surfaces stay smooth and machined edges stay sharp. The result has
// one vertex per triangle corner.
MeshData with_crease_normals(const std::vector<Eigen::Vector3f>& positions,
                             const std::vector<std::uint32_t>& indices,
                             const std::vector<std::array<std::uint8_t, 4>>& colors,
                             float crease_deg = 35.0f);

}  // namespace stanceplan::render
