// Benchmark of the exact normal contact solver (NormCG) on a non-Hertzian wheel/rail-like patch
// (bench/wheel_rail_patch.hpp): IBASE=2 profile, dx = dy = 0.1 mm, approach prescribed.
// Grids 71×81, 143×163, 287×323, 575×647. Reports per size the solve time (operators and FFT
// plans cached, as in a sequence of cases), CG iterations, elements in contact, and the time of
// one forward+inverse FFT pair of the padded product for comparison with the per-iteration cost.
//
// Reference (CONTACT, gfortran -O2 + FFTW, one thread): 0.04 / 0.27 / 1.35 / 7.3 s and
// 19 / 22 / 27 / 31 CG iterations.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <complex>
#include <vector>

#include "core/fft_backend.hpp"
#include "rollcontact/solve.hpp"
#include "wheel_rail_patch.hpp"

namespace {

using namespace rollcontact;

struct Size {
  int mx, my;
  double scale;
};
constexpr Size sizes[] = {{71, 81, 1.0}, {143, 163, 2.0}, {287, 323, 4.0}, {575, 647, 8.0}};

/// Time of one forward + inverse FFT pair of the padded product (≥ 2mx−1 × 2my−1) [s].
double fft_pair_seconds(const Grid& grid, FftPlanning planning) {
  auto engine = core::make_fft_engine(FftBackendKind::Default, core::good_fft_size(2 * grid.mx - 1),
                                      core::good_fft_size(2 * grid.my - 1), planning);
  std::vector<double> real(engine->real_size(), 0.0);
  std::vector<std::complex<double>> spectrum(engine->spectrum_size());
  for (std::size_t i = 0; i < real.size(); ++i) real[i] = static_cast<double>(i % 7);
  const int repeats = grid.mx > 300 ? 10 : 50;
  engine->forward(real.data(), spectrum.data());
  engine->inverse(spectrum.data(), real.data());
  const auto t0 = std::chrono::steady_clock::now();
  for (int k = 0; k < repeats; ++k) {
    engine->forward(real.data(), spectrum.data());
    engine->inverse(spectrum.data(), real.data());
  }
  const auto t1 = std::chrono::steady_clock::now();
  return std::chrono::duration<double>(t1 - t0).count() / repeats;
}

void BM_NormalProblem(benchmark::State& bstate) {
  const Size size = sizes[bstate.range(0)];
  const model::PatchProblem problem = bench::wheel_rail_patch(size.mx, size.my, size.scale);
  SolveOptions options;
  options.fft_planning = bstate.range(1) ? FftPlanning::Measure : FftPlanning::Estimate;
  PatchSolver state(options);
  Solution sol = state.solve(problem);  // builds and caches kernels, plans, preconditioner
  for (auto _ : bstate) {
    sol = state.solve(problem);
    const double kept = sol.totals.fn;  // a const operand: 1.7's DoNotOptimize(T&) corrupts doubles
    benchmark::DoNotOptimize(kept);
  }
  const double pair = fft_pair_seconds(sol.grid, options.fft_planning);
  bstate.counters["cg_iterations"] = sol.solver.normal_iterations;
  bstate.counters["products"] = sol.solver.normal_products;
  bstate.counters["coarse_its"] = sol.solver.normal_coarse_iterations;
  bstate.counters["ncon"] = sol.statistics.ncon;
  bstate.counters["npot"] = sol.statistics.npot;
  bstate.counters["converged"] = sol.solver.converged ? 1 : 0;
  bstate.counters["fft_pair_ms"] = pair * 1e3;
  const double per_iteration =
      sol.solver.normal_iteration_seconds / std::max(1, sol.solver.normal_iterations);
  bstate.counters["ms_per_cg_it"] = per_iteration * 1e3;
  bstate.counters["it_per_pair"] = per_iteration / pair;
  bstate.SetLabel(std::to_string(size.mx) + "x" + std::to_string(size.my) +
                  (bstate.range(1) ? " fftw-measure" : " fftw-estimate"));
}
// Arguments: grid index 0..3, FFT planning (0 estimate = default, 1 measure).
BENCHMARK(BM_NormalProblem)
    ->ArgsProduct({{0, 1, 2, 3}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
