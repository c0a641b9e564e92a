// Benchmark of the exact tangential solvers on the wheel/rail-like patch of
// bench/wheel_rail_patch.hpp (IBASE=2 profile, dx = dy = 0.1 mm, approach prescribed, μ = 0.3):
//  - shift (T=1, TangCG) with shifts ξ = 0.0005 mm, φ = 0.0003 rad;
//  - steady rolling (T=3, SteadyGS) with creepages ξ = 0.0005, φ = 0.0003 rad/mm;
//  - steady rolling with the forces prescribed (F=2, the forces of the creepage-driven case).
// Grids 71×81, 143×163, 287×323. Reports time, tangential iterations and Newton iterations.
//
// Reference (CONTACT, gfortran, one thread): shift 0.20 / 1.13 / 11.1 s; steady rolling
// 0.62 / 4.84 / 40.7 s; steady rolling with forces prescribed 6.2 / 58 s (first two grids).

#include <benchmark/benchmark.h>

#include <string>

#include "rollcontact/solve.hpp"
#include "wheel_rail_patch.hpp"

namespace {

using namespace rollcontact;

struct Size {
  int mx, my;
  double scale;
};
constexpr Size sizes[] = {{71, 81, 1.0}, {143, 163, 2.0}, {287, 323, 4.0}};

model::PatchProblem tangential_case(const Size& size, int t) {
  model::PatchProblem p = bench::wheel_rail_patch(size.mx, size.my, size.scale);
  p.tangential.kind = t == 1   ? model::TangentialKind::Shift
                      : t == 2 ? model::TangentialKind::TransientRolling
                               : model::TangentialKind::SteadyRolling;
  p.friction = {0.3, 0.3};
  p.tangential.creepage.longitudinal = 0.0005;
  p.tangential.creepage.spin_rad_per_mm = 0.0003;
  p.rolling.direction_rad = 0.0;
  p.rolling.step_mm = 0.1;
  p.rolling.velocity_mm_per_s = 10000.0;
  p.solver.max_inner_iterations = 999;
  p.solver.max_newton_iterations = 30;
  return p;
}

void report(benchmark::State& bstate, const Solution& sol, const Size& size) {
  bstate.counters["tang_iterations"] = sol.solver.tangential_iterations;
  bstate.counters["newton_iterations"] = sol.solver.newton_iterations;
  bstate.counters["coarse_its"] = sol.solver.tangential_coarse_iterations;
  bstate.counters["ncon"] = sol.statistics.ncon;
  bstate.counters["nslip"] = sol.statistics.nslip;
  bstate.counters["converged"] = sol.solver.converged ? 1 : 0;
  bstate.SetLabel(std::to_string(size.mx) + "x" + std::to_string(size.my));
}

void run(benchmark::State& bstate, const model::PatchProblem& problem, const Size& size) {
  PatchSolver state;
  Solution sol = state.solve(problem);  // builds and caches the operators
  for (auto _ : bstate) {
    sol = state.solve(problem);
    const double kept = sol.totals.fx;  // a const operand: 1.7's DoNotOptimize(T&) corrupts doubles
    benchmark::DoNotOptimize(kept);
  }
  report(bstate, sol, size);
}

void BM_Shift(benchmark::State& bstate) {
  const Size size = sizes[bstate.range(0)];
  run(bstate, tangential_case(size, 1), size);
}

void BM_SteadyRolling(benchmark::State& bstate) {
  const Size size = sizes[bstate.range(0)];
  run(bstate, tangential_case(size, 3), size);
}

void BM_SteadyRollingForcesPrescribed(benchmark::State& bstate) {
  const Size size = sizes[bstate.range(0)];
  model::PatchProblem creep = tangential_case(size, 3);
  PatchSolver probe;
  const Solution reference = probe.solve(creep);
  model::PatchProblem forces = creep;
  forces.tangential.prescribed = model::TangentialPrescribed::Forces;
  forces.tangential.force_x_over_mu_fn = reference.totals.fx / (0.3 * reference.totals.fn);
  forces.tangential.force_y_over_mu_fn = reference.totals.fy / (0.3 * reference.totals.fn);
  run(bstate, forces, size);
}

BENCHMARK(BM_Shift)->DenseRange(0, 2)->Unit(benchmark::kMillisecond)->UseRealTime()->Iterations(1);
BENCHMARK(BM_SteadyRolling)
    ->DenseRange(0, 2)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);
BENCHMARK(BM_SteadyRollingForcesPrescribed)
    ->DenseRange(0, 1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
