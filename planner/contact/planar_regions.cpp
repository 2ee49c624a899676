#include "planner/contact/planar_regions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <unordered_map>
#include <utility>

namespace stanceplan {
namespace {

constexpr double kWeldDistance = 1e-6;  // m

// The mesh with close vertices merged; a degenerate triangle has area 0 and is skipped.
struct WeldedMesh {
  std::vector<Eigen::Vector3d> vertices;
  std::vector<Eigen::Vector3i> triangles;
  std::vector<Eigen::Vector3d> normals;
  std::vector<double> areas;
  bool valid(int t) const { return areas[t] > 0.0; }
};

struct GridKeyHash {
  size_t operator()(const std::array<int64_t, 3>& k) const {
    uint64_t h = 1469598103934665603ull;
    for (int64_t c : k) h = (h ^ static_cast<uint64_t>(c)) * 1099511628211ull;
    return static_cast<size_t>(h);
  }
};

WeldedMesh weld(const std::vector<Eigen::Vector3d>& vertices,
                const std::vector<Eigen::Vector3i>& triangles) {
  WeldedMesh m;
  std::unordered_map<std::array<int64_t, 3>, int, GridKeyHash> index;
  index.reserve(vertices.size());
  std::vector<int> welded(vertices.size());
  for (size_t i = 0; i < vertices.size(); ++i) {
    std::array<int64_t, 3> key;
    for (int k = 0; k < 3; ++k) key[k] = std::llround(vertices[i][k] / kWeldDistance);
    const auto [it, inserted] = index.emplace(key, static_cast<int>(m.vertices.size()));
    if (inserted) m.vertices.push_back(vertices[i]);
    welded[i] = it->second;
  }
  const int n = static_cast<int>(vertices.size());
  for (const Eigen::Vector3i& t : triangles) {
    const bool in_range = (t.array() >= 0).all() && (t.array() < n).all();
    Eigen::Vector3i w = Eigen::Vector3i::Zero();
    Eigen::Vector3d c = Eigen::Vector3d::Zero();
    if (in_range) {
      w = Eigen::Vector3i(welded[t[0]], welded[t[1]], welded[t[2]]);
      c = (m.vertices[w[1]] - m.vertices[w[0]]).cross(m.vertices[w[2]] - m.vertices[w[0]]);
    }
    const double area = 0.5 * c.norm();
    const bool valid = area > 1e-14 && w[0] != w[1] && w[1] != w[2] && w[0] != w[2];
    m.triangles.push_back(w);
    m.normals.push_back(valid ? c.normalized() : Eigen::Vector3d::Zero());
    m.areas.push_back(valid ? area : 0.0);
  }
  return m;
}

uint64_t edge_key(int a, int b) {
  return (static_cast<uint64_t>(static_cast<uint32_t>(a)) << 32) | static_cast<uint32_t>(b);
}

// Triangles sharing an edge (either direction), as compressed rows: the neighbours of t are
// neighbours[start[t] .. start[t + 1]).
struct Adjacency {
  std::vector<int> start;
  std::vector<int> neighbours;
};

Adjacency edge_adjacency(const WeldedMesh& m) {
  const int n = static_cast<int>(m.triangles.size());
  std::vector<std::pair<uint64_t, int>> edges;
  edges.reserve(3 * n);
  for (int t = 0; t < n; ++t) {
    if (!m.valid(t)) continue;
    for (int k = 0; k < 3; ++k) {
      const int a = m.triangles[t][k], b = m.triangles[t][(k + 1) % 3];
      edges.emplace_back(edge_key(std::min(a, b), std::max(a, b)), t);
    }
  }
  std::sort(edges.begin(), edges.end());
  std::vector<std::pair<int, int>> pairs;
  for (size_t i = 0; i < edges.size();) {
    size_t j = i;
    while (j < edges.size() && edges[j].first == edges[i].first) ++j;
    for (size_t p = i; p < j; ++p)
      for (size_t q = i; q < j; ++q)
        if (p != q) pairs.emplace_back(edges[p].second, edges[q].second);
    i = j;
  }
  std::sort(pairs.begin(), pairs.end());
  Adjacency adjacency;
  adjacency.start.assign(n + 1, 0);
  for (const auto& [t, u] : pairs) ++adjacency.start[t + 1];
  for (int t = 0; t < n; ++t) adjacency.start[t + 1] += adjacency.start[t];
  for (const auto& pair : pairs) adjacency.neighbours.push_back(pair.second);
  return adjacency;
}

// Region growing from each triangle not yet taken, in index order: lists of triangles.
std::vector<std::vector<int>> grow_regions(const WeldedMesh& m, const Adjacency& adjacency,
                                           const PlanarRegionOptions& options) {
  const int n = static_cast<int>(m.triangles.size());
  const double min_cos = std::cos(options.angle_tolerance);
  std::vector<int> region_of(n, -1);
  std::vector<std::vector<int>> regions;
  std::deque<int> queue;
  for (int seed = 0; seed < n; ++seed) {
    if (!m.valid(seed) || region_of[seed] >= 0) continue;
    const int r = static_cast<int>(regions.size());
    const Eigen::Vector3d n0 = m.normals[seed];
    const Eigen::Vector3d p0 = m.vertices[m.triangles[seed][0]];
    auto accepts = [&](int t) {
      if (!m.valid(t) || region_of[t] >= 0 || m.normals[t].dot(n0) < min_cos) return false;
      for (int k = 0; k < 3; ++k)
        if (std::abs(n0.dot(m.vertices[m.triangles[t][k]] - p0)) > options.offset_tolerance)
          return false;
      return true;
    };
    regions.emplace_back();
    region_of[seed] = r;
    queue.push_back(seed);
    while (!queue.empty()) {
      const int t = queue.front();
      queue.pop_front();
      regions[r].push_back(t);
      for (int i = adjacency.start[t]; i < adjacency.start[t + 1]; ++i) {
        const int u = adjacency.neighbours[i];
        if (!accepts(u)) continue;
        region_of[u] = r;
        queue.push_back(u);
      }
    }
  }
  return regions;
}

void fit_plane(const WeldedMesh& m, PlanarRegion* region) {
  Eigen::Vector3d normal = Eigen::Vector3d::Zero(), centroid = Eigen::Vector3d::Zero();
  double area = 0.0;
  for (int t : region->triangles) {
    const Eigen::Vector3i& f = m.triangles[t];
    normal += m.areas[t] * m.normals[t];
    centroid += m.areas[t] * (m.vertices[f[0]] + m.vertices[f[1]] + m.vertices[f[2]]) / 3.0;
    area += m.areas[t];
  }
  region->area = area;
  region->origin = centroid / area;
  region->normal = normal.normalized();
  const Eigen::Vector3d& z = region->normal;
  for (int i = 0; i < 3; ++i) {
    const Eigen::Vector3d e = Eigen::Vector3d::Unit(i);
    if (std::abs(e.dot(z)) < 0.9) {
      region->x_axis = (e - e.dot(z) * z).normalized();
      break;
    }
  }
  region->y_axis = z.cross(region->x_axis);
}

// The region's directed edges whose reverse is not in the region: its boundary, interior on the
// left (the triangles are counter-clockwise about the normal).
std::vector<std::pair<int, int>> boundary_edges(const WeldedMesh& m,
                                                const std::vector<int>& triangles) {
  std::vector<uint64_t> directed;
  directed.reserve(3 * triangles.size());
  for (int t : triangles)
    for (int k = 0; k < 3; ++k)
      directed.push_back(edge_key(m.triangles[t][k], m.triangles[t][(k + 1) % 3]));
  std::sort(directed.begin(), directed.end());
  std::vector<std::pair<int, int>> out;
  for (uint64_t e : directed) {
    const int a = static_cast<int>(e >> 32), b = static_cast<int>(e & 0xffffffffu);
    if (!std::binary_search(directed.begin(), directed.end(), edge_key(b, a)))
      out.emplace_back(a, b);
  }
  return out;
}

// Clockwise angle in (0, 2 pi] from direction r to direction c.
double clockwise_angle(const Eigen::Vector2d& r, const Eigen::Vector2d& c) {
  double a = std::atan2(c.x() * r.y() - c.y() * r.x(), r.dot(c));
  return a <= 0.0 ? a + 2.0 * M_PI : a;
}

// Boundary edges chained into closed loops of vertex indices. Where the region touches itself at a
// vertex (two ways on), the loop takes the first way clockwise from the way it came in, which
// keeps each loop simple.
std::vector<std::vector<int>> chain_loops(std::vector<std::pair<int, int>> edges,
                                          const std::unordered_map<int, Eigen::Vector2d>& p) {
  std::sort(edges.begin(), edges.end());
  std::vector<bool> used(edges.size(), false);
  std::vector<std::vector<int>> loops;
  for (size_t e0 = 0; e0 < edges.size(); ++e0) {
    if (used[e0]) continue;
    std::vector<int> loop;
    size_t e = e0;
    bool closed = false;
    while (true) {
      used[e] = true;
      loop.push_back(edges[e].first);
      const int v = edges[e].second;
      if (v == edges[e0].first) {
        closed = true;
        break;
      }
      auto it = std::lower_bound(edges.begin(), edges.end(), std::make_pair(v, -1));
      size_t best = edges.size();
      double best_angle = 10.0;
      const Eigen::Vector2d back = p.at(edges[e].first) - p.at(v);
      for (; it != edges.end() && it->first == v; ++it) {
        const size_t c = static_cast<size_t>(it - edges.begin());
        if (used[c]) continue;
        const double angle = clockwise_angle(back, p.at(it->second) - p.at(v));
        if (angle < best_angle) best = c, best_angle = angle;
      }
      if (best == edges.size()) break;  // an open chain: a non-manifold mesh
      e = best;
    }
    if (closed && loop.size() >= 3) loops.push_back(std::move(loop));
  }
  return loops;
}

bool inside(const Polygon2& polygon, const Eigen::Vector2d& q) {
  bool in = false;
  for (size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d &a = polygon[i], &b = polygon[j];
    if ((a.y() > q.y()) != (b.y() > q.y()) &&
        q.x() < (b.x() - a.x()) * (q.y() - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

void outline(const WeldedMesh& m, PlanarRegion* region) {
  std::unordered_map<int, Eigen::Vector2d> p;
  for (int t : region->triangles)
    for (int k = 0; k < 3; ++k) {
      const int v = m.triangles[t][k];
      const Eigen::Vector3d d = m.vertices[v] - region->origin;
      p.emplace(v, Eigen::Vector2d(d.dot(region->x_axis), d.dot(region->y_axis)));
    }
  std::vector<Polygon2> holes;
  for (const std::vector<int>& loop : chain_loops(boundary_edges(m, region->triangles), p)) {
    Polygon2 polygon;
    for (int v : loop) polygon.push_back(p.at(v));
    if (signed_area2(polygon) > 0.0)
      region->outlines.push_back({std::move(polygon), {}});
    else
      holes.push_back(std::move(polygon));
  }
  for (Polygon2& hole : holes)
    for (RegionOutline& o : region->outlines)
      if (inside(o.outer, hole[0])) {
        o.holes.push_back(std::move(hole));
        break;
      }
}

}  // namespace

std::vector<PlanarRegion> find_planar_regions(const std::vector<Eigen::Vector3d>& vertices,
                                              const std::vector<Eigen::Vector3i>& triangles,
                                              const PlanarRegionOptions& options) {
  const WeldedMesh m = weld(vertices, triangles);
  const Adjacency adjacency = edge_adjacency(m);
  std::vector<PlanarRegion> regions;
  for (std::vector<int>& members : grow_regions(m, adjacency, options)) {
    PlanarRegion region;
    region.triangles = std::move(members);
    fit_plane(m, &region);
    outline(m, &region);
    regions.push_back(std::move(region));
  }
  return regions;
}

}  // namespace stanceplan
