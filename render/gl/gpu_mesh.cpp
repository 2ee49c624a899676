#include "render/gl/gpu_mesh.h"

#include <cstddef>
#include <cstring>
#include <vector>

#include "render/gl/gl.h"

namespace stanceplan::render {
namespace {

// Interleaved vertex: position, normal, colour (white when the mesh has none).
struct Vertex {
  float position[3];
  float normal[3];
  std::uint8_t color[4];
};

}  // namespace

GpuMesh::GpuMesh(const MeshData& mesh) : count_(static_cast<int>(mesh.indices.size())) {
  has_colors_ = mesh.colors.size() == mesh.positions.size() && !mesh.colors.empty();
  std::vector<Vertex> vertices(mesh.positions.size());
  for (size_t i = 0; i < vertices.size(); ++i) {
    std::memcpy(vertices[i].position, mesh.positions[i].data(), sizeof(vertices[i].position));
    std::memcpy(vertices[i].normal, mesh.normals[i].data(), sizeof(vertices[i].normal));
    const std::array<std::uint8_t, 4> white = {255, 255, 255, 255};
    std::memcpy(vertices[i].color, (has_colors_ ? mesh.colors[i] : white).data(), 4);
  }
  glGenVertexArrays(1, &vao_);
  glBindVertexArray(vao_);
  glGenBuffers(1, &vbo_);
  glBindBuffer(GL_ARRAY_BUFFER, vbo_);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(Vertex)),
               vertices.data(), GL_STATIC_DRAW);
  glGenBuffers(1, &ebo_);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, ebo_);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER,
               static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 4, GL_UNSIGNED_BYTE, GL_TRUE, sizeof(Vertex),
                        reinterpret_cast<void*>(offsetof(Vertex, color)));
  glBindVertexArray(0);
}

GpuMesh::~GpuMesh() {
  glDeleteBuffers(1, &ebo_);
  glDeleteBuffers(1, &vbo_);
  glDeleteVertexArrays(1, &vao_);
}

void GpuMesh::draw() const {
  glBindVertexArray(vao_);
  glDrawElements(GL_TRIANGLES, count_, GL_UNSIGNED_INT, nullptr);
}

}  // namespace stanceplan::render
