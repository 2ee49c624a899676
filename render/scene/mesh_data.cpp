#include "render/scene/mesh_data.h"

#include <cmath>
#include <cstring>
#include <numbers>
#include <unordered_map>

namespace stanceplan::render {
namespace {

constexpr float kPi = std::numbers::pi_v<float>;

std::uint32_t add_vertex(MeshData& m, const Eigen::Vector3f& p, const Eigen::Vector3f& n) {
  m.positions.push_back(p);
  m.normals.push_back(n);
  return static_cast<std::uint32_t>(m.positions.size() - 1);
}

void add_triangle(MeshData& m, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  m.indices.insert(m.indices.end(), {a, b, c});
}

// A ring of `segments` + 1 vertices (the seam is duplicated) at height z.
void add_disk(MeshData& m, float z, bool facing_up, int segments) {
  const Eigen::Vector3f n(0.0f, 0.0f, facing_up ? 1.0f : -1.0f);
  const std::uint32_t centre = add_vertex(m, Eigen::Vector3f(0.0f, 0.0f, z), n);
  for (int i = 0; i <= segments; ++i) {
    const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
    add_vertex(m, Eigen::Vector3f(std::cos(a), std::sin(a), z), n);
  }
  for (int i = 0; i < segments; ++i) {
    const std::uint32_t a = centre + 1 + i, b = centre + 2 + i;
    facing_up ? add_triangle(m, centre, a, b) : add_triangle(m, centre, b, a);
  }
}

// For every vertex, the index of the first vertex at exactly the same position.
std::vector<std::uint32_t> weld_positions(const std::vector<Eigen::Vector3f>& positions) {
  struct KeyHash {
    size_t operator()(const std::array<std::uint32_t, 3>& k) const {
      return (static_cast<size_t>(k[0]) * 73856093u) ^ (static_cast<size_t>(k[1]) * 19349663u) ^
             (static_cast<size_t>(k[2]) * 83492791u);
    }
  };
  std::unordered_map<std::array<std::uint32_t, 3>, std::uint32_t, KeyHash> first;
  first.reserve(positions.size());
  std::vector<std::uint32_t> weld(positions.size());
  for (size_t i = 0; i < positions.size(); ++i) {
    std::array<std::uint32_t, 3> key;
    std::memcpy(key.data(), positions[i].data(), sizeof(key));
    weld[i] = first.emplace(key, static_cast<std::uint32_t>(i)).first->second;
  }
  return weld;
}

}  // namespace

Eigen::AlignedBox3f MeshData::bounds() const {
  if (!box_.isEmpty() || positions.empty()) return box_;
  Eigen::AlignedBox3f box;
  for (const Eigen::Vector3f& p : positions) box.extend(p);
  return box;
}

void MeshData::update_bounds() {
  box_.setEmpty();
  for (const Eigen::Vector3f& p : positions) box_.extend(p);
}

void MeshData::append(const MeshData& other) {
  const auto first = static_cast<std::uint32_t>(positions.size());
  const bool keep_colors =
      colors.size() == positions.size() && other.colors.size() == other.positions.size();
  positions.insert(positions.end(), other.positions.begin(), other.positions.end());
  normals.insert(normals.end(), other.normals.begin(), other.normals.end());
  if (keep_colors)
    colors.insert(colors.end(), other.colors.begin(), other.colors.end());
  else
    colors.clear();
  for (std::uint32_t i : other.indices) indices.push_back(first + i);
  update_bounds();
}

MeshData unit_box() {
  MeshData m;
  for (int axis = 0; axis < 3; ++axis) {
    for (float sign : {-1.0f, 1.0f}) {
      Eigen::Vector3f n = Eigen::Vector3f::Zero();
      n[axis] = sign;
      // Two in-face axes u, v with u x v = n.
      Eigen::Vector3f u = Eigen::Vector3f::Zero(), v;
      u[(axis + 1) % 3] = 1.0f;
      v = n.cross(u);
      const std::uint32_t first = static_cast<std::uint32_t>(m.positions.size());
      for (int k = 0; k < 4; ++k) {
        const float su = (k == 1 || k == 2) ? 0.5f : -0.5f, sv = k >= 2 ? 0.5f : -0.5f;
        add_vertex(m, 0.5f * n + su * u + sv * v, n);
      }
      add_triangle(m, first, first + 1, first + 2);
      add_triangle(m, first, first + 2, first + 3);
    }
  }
  m.update_bounds();
  return m;
}

MeshData unit_cylinder(int segments) {
  MeshData m;
  for (int i = 0; i <= segments; ++i) {
    const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
    const Eigen::Vector3f radial(std::cos(a), std::sin(a), 0.0f);
    add_vertex(m, radial + Eigen::Vector3f(0, 0, -0.5f), radial);
    add_vertex(m, radial + Eigen::Vector3f(0, 0, 0.5f), radial);
  }
  for (int i = 0; i < segments; ++i) {
    const std::uint32_t b0 = 2 * i, t0 = 2 * i + 1, b1 = 2 * i + 2, t1 = 2 * i + 3;
    add_triangle(m, b0, b1, t1);
    add_triangle(m, b0, t1, t0);
  }
  add_disk(m, 0.5f, true, segments);
  add_disk(m, -0.5f, false, segments);
  m.update_bounds();
  return m;
}

MeshData unit_sphere(int slices, int stacks) {
  MeshData m;
  for (int j = 0; j <= stacks; ++j) {
    const float polar = kPi * static_cast<float>(j) / static_cast<float>(stacks);
    for (int i = 0; i <= slices; ++i) {
      const float a = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(slices);
      const Eigen::Vector3f n(std::sin(polar) * std::cos(a), std::sin(polar) * std::sin(a),
                              std::cos(polar));
      add_vertex(m, n, n);
    }
  }
  const int row = slices + 1;
  for (int j = 0; j < stacks; ++j) {
    for (int i = 0; i < slices; ++i) {
      const std::uint32_t a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      if (j > 0) add_triangle(m, a, c, b);
      if (j < stacks - 1) add_triangle(m, b, c, d);
    }
  }
  m.update_bounds();
  return m;
}

MeshData unit_cone(int segments) {
  MeshData m;
  const float s = std::sqrt(0.5f);  // the side of a cone of radius 1 and height 1 leans 45 degrees
  for (int i = 0; i < segments; ++i) {
    const float a0 = 2.0f * kPi * static_cast<float>(i) / static_cast<float>(segments);
    const float a1 = 2.0f * kPi * static_cast<float>(i + 1) / static_cast<float>(segments);
    const float am = 0.5f * (a0 + a1);
    const Eigen::Vector3f n0(s * std::cos(a0), s * std::sin(a0), s),
        n1(s * std::cos(a1), s * std::sin(a1), s);
    const std::uint32_t p0 = add_vertex(m, Eigen::Vector3f(std::cos(a0), std::sin(a0), 0), n0);
    const std::uint32_t p1 = add_vertex(m, Eigen::Vector3f(std::cos(a1), std::sin(a1), 0), n1);
    const std::uint32_t apex = add_vertex(m, Eigen::Vector3f(0, 0, 1),
                                          Eigen::Vector3f(s * std::cos(am), s * std::sin(am), s));
    add_triangle(m, p0, p1, apex);
  }
  add_disk(m, 0.0f, false, segments);
  m.update_bounds();
  return m;
}

MeshData polygon(const std::vector<Eigen::Vector3f>& vertices, const Eigen::Vector3f& normal) {
  MeshData m;
  const Eigen::Vector3f n = normal.normalized();
  for (const Eigen::Vector3f& v : vertices) add_vertex(m, v, n);
  for (std::uint32_t i = 1; i + 1 < vertices.size(); ++i) add_triangle(m, 0, i, i + 1);
  m.update_bounds();
  return m;
}

MeshData polygon_ring(const std::vector<Eigen::Vector3f>& vertices, const Eigen::Vector3f& normal,
                      float width) {
  MeshData m;
  const Eigen::Vector3f n = normal.normalized();
  const size_t count = vertices.size();
  if (count < 3) return m;
  std::vector<Eigen::Vector3f> out_edge(count);  // outward unit normal of edge i -> i+1, in-plane
  for (size_t i = 0; i < count; ++i)
    out_edge[i] = (vertices[(i + 1) % count] - vertices[i]).cross(n).normalized();
  for (size_t i = 0; i < count; ++i) {
    const Eigen::Vector3f& a = out_edge[(i + count - 1) % count];
    const Eigen::Vector3f& b = out_edge[i];
    const Eigen::Vector3f miter =
        (a + b) / std::max(1.0f + a.dot(b), 0.2f);  // keeps width on both edges
    add_vertex(m, vertices[i], n);
    add_vertex(m, vertices[i] + width * miter, n);
  }
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::uint32_t j = (i + 1) % count;
    add_triangle(m, 2 * i, 2 * i + 1, 2 * j + 1);
    add_triangle(m, 2 * i, 2 * j + 1, 2 * j);
  }
  m.update_bounds();
  return m;
}

MeshData with_crease_normals(const std::vector<Eigen::Vector3f>& positions,
                             const std::vector<std::uint32_t>& indices,
                             const std::vector<std::array<std::uint8_t, 4>>& colors,
                             float crease_deg) {
  const size_t num_faces = indices.size() / 3;
  std::vector<Eigen::Vector3f> area_normal(num_faces), unit_normal(num_faces);
  for (size_t f = 0; f < num_faces; ++f) {
    const Eigen::Vector3f& a = positions[indices[3 * f]];
    area_normal[f] = (positions[indices[3 * f + 1]] - a).cross(positions[indices[3 * f + 2]] - a);
    const float norm = area_normal[f].norm();
    unit_normal[f] = norm > 0.0f ? Eigen::Vector3f(area_normal[f] / norm) : Eigen::Vector3f::Zero();
  }
  // Faces around each welded vertex (compressed rows). Welding by exact position matters for STL
  // files, whose per-face normals keep assimp from joining the corners of neighbouring faces.
  const std::vector<std::uint32_t> weld = weld_positions(positions);
  std::vector<std::uint32_t> start(positions.size() + 1, 0), faces(indices.size());
  for (std::uint32_t v : indices) ++start[weld[v] + 1];
  for (size_t v = 0; v < positions.size(); ++v) start[v + 1] += start[v];
  std::vector<std::uint32_t> fill(start.begin(), start.end() - 1);
  for (size_t i = 0; i < indices.size(); ++i)
    faces[fill[weld[indices[i]]]++] = static_cast<std::uint32_t>(i / 3);

  const float cos_crease = std::cos(crease_deg * kPi / 180.0f);
  const bool has_colors = colors.size() == positions.size();
  MeshData m;
  // Corners with the same position, normal and colour share one output vertex: on smooth meshes
  // that divides the vertex count (and llvmpipe's vertex work) several times.
  struct CornerHash {
    size_t operator()(const std::array<std::uint32_t, 5>& k) const {
      size_t h = 1469598103934665603ull;
      for (std::uint32_t x : k) h = (h ^ x) * 1099511628211ull;
      return h;
    }
  };
  std::unordered_map<std::array<std::uint32_t, 5>, std::uint32_t, CornerHash> shared;
  shared.reserve(indices.size());
  for (size_t f = 0; f < num_faces; ++f) {
    if (unit_normal[f].isZero()) continue;  // degenerate triangle: nothing to draw
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t v = indices[3 * f + k], w = weld[v];
      Eigen::Vector3f n = Eigen::Vector3f::Zero();
      for (std::uint32_t i = start[w]; i < start[w + 1]; ++i)
        if (unit_normal[faces[i]].dot(unit_normal[f]) >= cos_crease) n += area_normal[faces[i]];
      n = n.squaredNorm() > 0.0f ? Eigen::Vector3f(n.normalized()) : unit_normal[f];
      std::array<std::uint32_t, 5> key;
      key[0] = w;
      std::memcpy(&key[1], n.data(), 3 * sizeof(float));
      key[4] = 0;
      if (has_colors) std::memcpy(&key[4], colors[v].data(), 4);
      const auto [it, added] = shared.emplace(key, static_cast<std::uint32_t>(m.positions.size()));
      if (added) {
        m.positions.push_back(positions[v]);
        m.normals.push_back(n);
        if (has_colors) m.colors.push_back(colors[v]);
      }
      m.indices.push_back(it->second);
    }
  }
  m.update_bounds();
  return m;
}

}  // namespace stanceplan::render
