// Off-screen rendering speed at 1280x720 for the humanoid standing on flat ground with its
// contact forces (the scene of a live search snapshot), as the renderer issue asks: render time
// (figure quality: 4x multisampling and shadows; the cheaper preview style for live snapshots,
// with and without shadows) and PNG encoding time (libpng, compression level 1). Run:
//   build/bench/render_bench --benchmark_repetitions=10 --benchmark_report_aggregates_only=true
// and read the medians. Targets on the 2-core machine: render <= 30 ms, encode <= 40 ms.
#include <benchmark/benchmark.h>

#include "planner/model/kinematics.h"
#include "render/image/png_io.h"
#include "render/renderer.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

struct Frame {
  Scene scene = test::humanoid_scene("flat_ground");
  Eigen::VectorXd q = test::standing_configuration(scene);
  std::vector<PlanContact> contacts;
  std::vector<VertexForce> forces;

  Frame() {
    const Entity& robot = scene.system.entity(0);
    ModelData data(robot);
    forward_kinematics(robot, q.segment(0, robot.nq()), data);
    for (const char* sole : {"robot/l_sole", "robot/r_sole"}) {
      contacts.push_back({test::task(scene, sole, "env/floor").contact, true});
      const Surface& s = scene.surfaces.get(contacts.back().contact.s1);
      for (const Eigen::Vector3d& p_L : s.vertices_L()) {
        VertexForce f;
        f.contact = static_cast<int>(contacts.size()) - 1;
        f.point_W = data.T_WL[s.link] * p_L;
        f.force_W = Eigen::Vector3d(0.0, 0.0, robot.model->total_mass * 9.81 / 8.0);
        forces.push_back(f);
      }
    }
  }
};

const Frame& frame() {
  static const Frame f;
  return f;
}

void render_frame(benchmark::State& state, const render::RenderStyle& style) {
  const Frame& f = frame();
  render::Renderer renderer(1280, 720, style);
  const render::Camera camera =
      renderer.frame(f.scene, f.q, f.contacts, render::View::ThreeQuarter);
  renderer.render(f.scene, f.q, f.contacts, f.forces, camera, "warm-up");  // shader compilation
  for (auto _ : state) {
    render::Image image = renderer.render(
        f.scene, f.q, f.contacts, f.forces, camera,
        "Step 3 of 12  \u00b7  add r_palm on wall\nstance: l_sole, r_sole on floor");
    benchmark::DoNotOptimize(image.rgba.data());
  }
  state.SetLabel(renderer.gl_renderer());
}

void BM_RenderFigure(benchmark::State& state) {
  render_frame(state, render::RenderStyle{});
}
void BM_RenderPreview(benchmark::State& state) {
  render_frame(state, render::RenderStyle::preview());
}
void BM_RenderPreviewNoShadows(benchmark::State& state) {
  render::RenderStyle style = render::RenderStyle::preview();
  style.shadows = false;
  render_frame(state, style);
}

void BM_EncodePng(benchmark::State& state) {
  const Frame& f = frame();
  render::Renderer renderer(1280, 720);
  const render::Image image =
      renderer.render(f.scene, f.q, f.contacts, f.forces,
                      renderer.frame(f.scene, f.q, f.contacts, render::View::ThreeQuarter),
                      "Step 3 of 12\nstance: l_sole, r_sole on floor");
  size_t bytes = 0;
  for (auto _ : state) {
    const std::string png = render::encode_png(image);
    bytes = png.size();
    benchmark::DoNotOptimize(png.data());
  }
  state.counters["kB"] = static_cast<double>(bytes) / 1024.0;
}

BENCHMARK(BM_RenderFigure)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RenderPreview)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_RenderPreviewNoShadows)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_EncodePng)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
}  // namespace stanceplan
