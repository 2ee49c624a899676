// Speed of surface extraction (`surfaces: auto`, planner/contact/affordances.h) on a 101,200-
// triangle environment mesh made here: an 11 x 11 m terrain of eleven 10 cm steps (1 m deep), in
// 5 cm cells of two triangles (8,800 per tread) with their risers, written once as a binary STL.
// Extraction covers reading the file (assimp), welding, region growing, outlines, convex pieces
// and naming; the regions alone are timed too. Run:
//   build/bench/affordances_bench --benchmark_repetitions=10
//   --benchmark_report_aggregates_only=true
// and read the medians. Target on the 2-core machine: extraction <= 1 s.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <filesystem>
#include <fstream>

#include "planner/contact/affordances.h"
#include "planner/contact/planar_regions.h"
#include "planner/model/mesh_file.h"
#include "planner/model/urdf_loader.h"

namespace stanceplan {
namespace {

namespace fs = std::filesystem;
using Eigen::Vector3d;

constexpr int kCells = 220;        // per side
constexpr double kCell = 0.05;     // m
constexpr int kCellsPerStep = 20;  // along x
constexpr double kRise = 0.1;      // m

void add_quad(std::vector<std::array<Vector3d, 3>>* tris, const Vector3d& a, const Vector3d& b,
              const Vector3d& c, const Vector3d& d) {
  tris->push_back({a, b, c});
  tris->push_back({a, c, d});
}

// The terrain's triangles, counter-clockwise seen from above (treads) or from -x (risers).
std::vector<std::array<Vector3d, 3>> terrain() {
  std::vector<std::array<Vector3d, 3>> tris;
  auto height = [](int i) { return kRise * (i / kCellsPerStep); };
  for (int i = 0; i < kCells; ++i)
    for (int j = 0; j < kCells; ++j) {
      const double x0 = i * kCell, x1 = x0 + kCell, y0 = j * kCell, y1 = y0 + kCell, z = height(i);
      add_quad(&tris, {x0, y0, z}, {x1, y0, z}, {x1, y1, z}, {x0, y1, z});
      if ((i + 1) % kCellsPerStep == 0 && i + 1 < kCells)  // the riser up to the next tread
        add_quad(&tris, {x1, y1, z}, {x1, y0, z}, {x1, y0, height(i + 1)}, {x1, y1, height(i + 1)});
    }
  return tris;
}

// Binary STL: 80-byte header, count, then per triangle a normal, 3 vertices (float) and 2 bytes.
std::string write_terrain() {
  const fs::path dir = fs::temp_directory_path() / "stanceplan_affordances_bench";
  fs::create_directories(dir);
  const std::vector<std::array<Vector3d, 3>> tris = terrain();
  std::ofstream stl(dir / "terrain.stl", std::ios::binary);
  const char header[80] = "stanceplan affordances_bench terrain";
  stl.write(header, 80);
  const uint32_t count = static_cast<uint32_t>(tris.size());
  stl.write(reinterpret_cast<const char*>(&count), 4);
  for (const auto& t : tris) {
    const Vector3d n = (t[1] - t[0]).cross(t[2] - t[0]).normalized();
    float values[12];
    for (int k = 0; k < 3; ++k) values[k] = static_cast<float>(n[k]);
    for (int v = 0; v < 3; ++v)
      for (int k = 0; k < 3; ++k) values[3 + 3 * v + k] = static_cast<float>(t[v][k]);
    stl.write(reinterpret_cast<const char*>(values), sizeof(values));
    const uint16_t attributes = 0;
    stl.write(reinterpret_cast<const char*>(&attributes), 2);
  }
  std::ofstream(dir / "terrain.urdf")
      << "<robot name=\"terrain\"><link name=\"terrain\"><collision><geometry><mesh "
         "filename=\"terrain.stl\"/></geometry></collision></link></robot>\n";
  return (dir / "terrain.urdf").string();
}

const Model& terrain_model() {
  static const Model model = load_urdf(write_terrain());
  return model;
}

void BM_ExtractAffordances(benchmark::State& state) {
  const Model& model = terrain_model();
  size_t supports = 0, surfaces = 0;
  for (auto _ : state) {
    const std::vector<Affordance> found = extract_affordances(model, Eigen::Isometry3d::Identity());
    surfaces = found.size();
    supports = 0;
    for (const Affordance& a : found) supports += a.kind == AffordanceClass::Support;
    benchmark::DoNotOptimize(found.data());
  }
  state.SetLabel(std::to_string(supports) + " supports, " + std::to_string(surfaces) + " surfaces");
}
BENCHMARK(BM_ExtractAffordances)->Unit(benchmark::kMillisecond);

void BM_PlanarRegionsOnly(benchmark::State& state) {
  const TriangleMesh mesh = load_mesh(terrain_model().links[0].collisions[0].shape.mesh_path);
  size_t regions = 0;
  for (auto _ : state) {
    regions = find_planar_regions(mesh.vertices, mesh.triangles).size();
    benchmark::DoNotOptimize(regions);
  }
  state.SetLabel(std::to_string(mesh.triangles.size()) + " triangles, " + std::to_string(regions) +
                 " regions");
}
BENCHMARK(BM_PlanarRegionsOnly)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace stanceplan
