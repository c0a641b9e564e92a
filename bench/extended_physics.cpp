// Benchmark of the extended physics of issue 13 at three grid sizes each, in-process (the
// whole-process timings of the shared examples are in docs/benchmarks.md):
//  - BM_FallingFrictionSteady: veldep_fric's case 1 — 2-D steady rolling of a 460 mm wheel on a
//    flat rail under 622 kN/200 mm, exponential falling friction (L=4), ξ = −0.001, solved from
//    zero slip velocity (INISLP=1) with the default solver — on 92, 368 and 1472 elements along
//    the 9.2 mm line (δx = 0.1, 0.025, 0.00625 mm);
//  - BM_PlasticLayerShifts: plastic_3bl's magnetite layer (G₃/h = 8832 N/mm³, τ_c0 = 560 N/mm²,
//    μ = 0.7) under a Hertzian 900 N load spread over 11×11, 21×21 and 41×41 elements, loaded by
//    four shifts of 0.03 mm, of which the last ones flow plastically in the centre.
// Counters: slip-velocity passes, tangential iterations (products or sweeps), NSLIP/NPLAST.

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "format/inp/inp_reader.hpp"
#include "format/inp/to_model.hpp"
#include "rollcontact/solve.hpp"

namespace {

using namespace rollcontact;

/// veldep_fric.inp case 1 with MX elements of δx = 9.2/MX mm on the same line.
model::PatchProblem falling_friction_case(int mx) {
  const double dx = 9.2 / mx;
  const std::string text = fmt::format(
      " 3  MODULE\n"
      "  203100     P-B-T-N-F-S\n"
      "  422020     L-D-C-M-Z-E\n"
      " 0401331   H-G-I-A-O-W-R\n"
      "  5000  2000    30      1     1e-7\n"
      "    1    1.1\n"
      " 622216.   -0.001 0.000    0.000\n"
      "   0.180    0.120      100.    0.0     0.0\n"
      "   0.000    1.000\n"
      "   0.000    {dx}    45000.\n"
      "   0.280    0.280    82000.   82000.\n"
      "    3\n"
      "  {mx}   1   -4.600    0.000    {dx}    200.0\n"
      "       2           1\n"
      "       2    0.000    460.0   -10.00    20.00\n"
      "   0.000    0.000\n"
      " 0  MODULE\n",
      fmt::arg("mx", mx), fmt::arg("dx", dx));
  return format::to_patch_problem(format::read_inp_string(text, "veldep_like.inp").at(0));
}

void BM_FallingFrictionSteady(benchmark::State& bstate) {
  const model::PatchProblem problem = falling_friction_case(static_cast<int>(bstate.range(0)));
  PatchSolver warm;
  Solution sol = warm.solve(problem);  // operators built once, as in a sequence
  for (auto _ : bstate) {
    PatchSolver fresh_state;  // no previous slip: every run starts from zero slip velocity
    sol = fresh_state.solve(problem);
    // Through a const copy: Debian's Google Benchmark 1.7.1 DoNotOptimize on a non-const double
    // lvalue ("+r" constraint under GCC 12) corrupts the value it is given.
    const double fx = sol.totals.fx;
    benchmark::DoNotOptimize(fx);
  }
  bstate.counters["passes"] = sol.solver.slip_velocity_passes;
  bstate.counters["tang_iterations"] = sol.solver.tangential_iterations;
  bstate.counters["nslip"] = sol.statistics.nslip;
  bstate.counters["abs_fx_over_fn"] = std::abs(sol.totals.fx) / sol.totals.fn;
  bstate.counters["converged"] = sol.solver.converged ? 1 : 0;
}
BENCHMARK(BM_FallingFrictionSteady)->Arg(92)->Arg(368)->Arg(1472)->Unit(benchmark::kMillisecond);

model::PatchProblem plastic_case(int m, double shift_mm, bool first) {
  model::PatchProblem p;
  p.normal.kind = model::NormalLoadKind::Force;
  p.normal.force_N = 900.0;
  p.potential.ipotcn = -3;
  p.potential.mx = p.potential.my = m;
  p.potential.values = {0.5, 0.5, 1.0, 0.0};
  p.bodies.body1 = p.bodies.body2 = {0.28, 82000.0};
  p.bodies.has_layer = true;
  p.bodies.layer = {176.63, 0.02, 560.0, 0.0};
  p.friction = {0.7, 0.7};
  p.tangential.kind = model::TangentialKind::Shift;
  p.tangential.creepage.longitudinal = -shift_mm;
  p.solver.tolerance = 1e-6;
  p.sequence.continue_previous = !first;
  return p;
}

void BM_PlasticLayerShifts(benchmark::State& bstate) {
  const int m = static_cast<int>(bstate.range(0));
  Solution sol;
  int iterations = 0;
  for (auto _ : bstate) {
    PatchSolver s;
    iterations = 0;
    for (int step = 0; step < 4; ++step) {
      sol = s.solve(plastic_case(m, 0.03, step == 0));
      iterations += sol.solver.tangential_iterations;
    }
    // Through a const copy: Debian's Google Benchmark 1.7.1 DoNotOptimize on a non-const double
    // lvalue ("+r" constraint under GCC 12) corrupts the value it is given.
    const double fx = sol.totals.fx;
    benchmark::DoNotOptimize(fx);
  }
  bstate.counters["tang_iterations"] = iterations;
  bstate.counters["nplast"] = sol.statistics.nplast;
  bstate.counters["nslip"] = sol.statistics.nslip;
  bstate.counters["abs_fx_N"] = std::abs(sol.totals.fx);
  bstate.counters["converged"] = sol.solver.converged ? 1 : 0;
}
BENCHMARK(BM_PlasticLayerShifts)->Arg(11)->Arg(21)->Arg(41)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
