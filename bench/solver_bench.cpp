// Solve time of the IK-statics program on the humanoid with 2, 3 and 4 contacts (feet on the
// floor, palms on the wall), cold (from the standing guess) and warm (from the solution of the
// same stance with the robot shifted by 2 cm), as the solver issue asks. Warm takes the
// solution's forces too (ContactTask::force_guess_W); WarmConfigurationOnly, as the search's
// candidates do, its configuration only (the solver starts from the forces that balance the robot
// there at least cost: planner/solver/force_balance.h). Experiment switches:
// bench/solver_switches.h. Run:
//   build/bench/solver_bench --benchmark_repetitions=20 --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <string>

#include "bench/solver_switches.h"
#include "planner/solver/posture_nlp.h"
#include "planner/solver/posture_solver.h"
#include "tests/support/scenes.h"

namespace stanceplan {
namespace {

const Scene& scene() {
  static const Scene s = test::humanoid_scene("wall");
  return s;
}

PostureRequest request(int contacts) {
  const Scene& s = scene();
  PostureRequest r;
  r.contacts = {test::task(s, "robot/l_sole", "env/floor"),
                test::task(s, "robot/r_sole", "env/floor")};
  if (contacts >= 3) r.contacts.push_back(test::task(s, "robot/r_palm", "env/wall"));
  if (contacts >= 4) r.contacts.push_back(test::task(s, "robot/l_palm", "env/wall"));
  r.q_init = test::standing_configuration(s);
  const Model& m = *s.system.entity(0).model;
  for (const char* side : {"r_", "l_"}) {
    if (contacts < (side[0] == 'r' ? 3 : 4)) continue;
    r.q_init[7 + m.find_dof(std::string(side) + "shoulder_p")] = -1.4;
    r.q_init[7 + m.find_dof(std::string(side) + "wrist_p")] = -1.2;
  }
  r.q_ref = r.q_init;
  return r;
}

// The solver's options with the experiment switches of bench/solver_switches.h.
SolverOptions options() {
  SolverOptions o;
  bench::apply_solver_switches(o);
  return o;
}

void report(benchmark::State& state, const PostureResult& result) {
  state.counters["iterations"] = result.iterations;
  state.counters["solved"] = result.status == PostureStatus::Solved;
}

void BM_Cold(benchmark::State& state) {
  const PostureSolver solver(scene(), options());
  const PostureRequest r = request(int(state.range(0)));
  PostureResult result;
  for (auto _ : state) result = solver.solve(r);
  report(state, result);
}

// Solves from near the solution of request(contacts): its configuration shifted by 2 cm (as the
// search's node gives) and, when `forces`, its forces at every vertex.
void warm(benchmark::State& state, bool forces) {
  const PostureSolver solver(scene(), options());
  PostureRequest r = request(int(state.range(0)));
  const PostureResult first = solver.solve(r);
  r.q_init = first.q;
  r.q_init[0] += 0.02;
  r.q_ref = first.q;
  if (forces)
    for (const VertexForce& f : first.forces) {
      auto& guess = r.contacts[size_t(f.contact)].force_guess_W;
      guess.resize(size_t(f.vertex) + 1);
      guess[size_t(f.vertex)] = f.force_W;
    }
  PostureResult result;
  for (auto _ : state) result = solver.solve(r);
  report(state, result);
}

void BM_Warm(benchmark::State& state) {
  warm(state, true);
}
void BM_WarmConfigurationOnly(benchmark::State& state) {
  warm(state, false);
}

double p95(const std::vector<double>& v) {
  std::vector<double> s = v;
  std::sort(s.begin(), s.end());
  return s[std::min(s.size() - 1, static_cast<size_t>(0.95 * s.size()))];
}

BENCHMARK(BM_Cold)->DenseRange(2, 4)->Unit(benchmark::kMillisecond)->ComputeStatistics("p95", p95);
BENCHMARK(BM_Warm)->DenseRange(2, 4)->Unit(benchmark::kMillisecond)->ComputeStatistics("p95", p95);
BENCHMARK(BM_WarmConfigurationOnly)
    ->DenseRange(2, 4)
    ->Unit(benchmark::kMillisecond)
    ->ComputeStatistics("p95", p95);

}  // namespace
}  // namespace stanceplan

namespace stanceplan {
namespace {

// One evaluation of every constraint Jacobian and the objective gradient (what a Lagrangian
// gradient costs), for the 2- and 4-contact programs.
void BM_JacobianEvaluation(benchmark::State& state) {
  const PostureRequest r = request(int(state.range(0)));
  const SolverOptions o = options();
  PostureSolver solver(scene(), o);
  PostureNlp nlp(scene(), r, o, {});
  Eigen::VectorXd x(nlp.n()), grad(nlp.n());
  nlp.starting_point(x.data());
  for (auto _ : state) {
    benchmark::DoNotOptimize(nlp.dense_jacobian(x.data(), true).data());
    nlp.objective_gradient(x.data(), false, grad.data());
  }
  state.counters["n"] = nlp.n();
  state.counters["m"] = nlp.m();
  state.counters["nnz"] = nlp.nnz();
}
BENCHMARK(BM_JacobianEvaluation)->Arg(2)->Arg(4)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace stanceplan
