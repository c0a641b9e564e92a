// Cost of the elastic operators the solvers are built from, on the grids of the problem
// benchmarks (71×81 … 575×647, dx = dy = 0.1 mm):
//  - one forward + inverse FFT pair of the zero-padded grid (the unit of cost);
//  - the tangential 2×2 block product u = A·(px, py) (two forward and two inverse transforms);
//  - the block-circulant tangential preconditioner (unpadded grid).
// Counter `in_pairs`: the operator's time divided by the time of one padded FFT pair, measured
// in the same process just before. "A CG iteration should cost little more than its FFTs."

#include <benchmark/benchmark.h>

#include <chrono>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "core/fft_backend.hpp"
#include "elastic/block_convolution.hpp"
#include "elastic/influence.hpp"
#include "tangential/tangential_preconditioner.hpp"

namespace {

using namespace rollcontact;
using elastic::Component;

struct Size {
  int mx, my;
};
constexpr Size sizes[] = {{71, 81}, {143, 163}, {287, 323}, {575, 647}};

Grid grid_of(const Size& s) {
  Grid g;
  g.mx = s.mx;
  g.my = s.my;
  g.dx = g.dy = 0.1;
  return g;
}

CombinedMaterial steel() {
  CombinedMaterial m;
  m.g = 82000.0;
  m.nu = 0.28;
  return m;
}

std::vector<double> random_field(std::size_t n, unsigned seed) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> v(n);
  for (auto& x : v) x = u(gen);
  return v;
}

/// An engine of the zero-padded size of the grid, filled with a random field.
std::unique_ptr<core::FftEngine> padded_engine(const Size& s) {
  auto engine = core::make_fft_engine(FftBackendKind::Default, core::good_fft_size(2 * s.mx - 1),
                                      core::good_fft_size(2 * s.my - 1));
  const auto field = random_field(engine->real_size(), 1);
  std::copy(field.begin(), field.end(), engine->real_data());
  return engine;
}

void fft_pair(core::FftEngine& engine) {
  engine.execute_forward(engine.n_slow());
  engine.execute_inverse(engine.n_slow());
  benchmark::DoNotOptimize(engine.real_data()[0]);
}

/// Seconds per forward+inverse pair of the padded real transform, from `reps` repetitions.
double seconds_per_pair(const Size& s, int reps) {
  auto engine = padded_engine(s);
  fft_pair(*engine);
  const auto start = std::chrono::steady_clock::now();
  for (int r = 0; r < reps; ++r) fft_pair(*engine);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / reps;
}

int repetitions(const Size& s) {
  return s.mx < 200 ? 50 : 10;
}

/// Runs `apply` in the benchmark loop and reports its cost in padded FFT pairs of grid s.
template <class Apply>
void run_in_pairs(benchmark::State& bstate, const Size& s, Apply&& apply) {
  const double pair = seconds_per_pair(s, repetitions(s));
  double total = 0.0;
  for (auto _ : bstate) {
    const auto start = std::chrono::steady_clock::now();
    apply();
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  bstate.counters["in_pairs"] = total / static_cast<double>(bstate.iterations()) / pair;
  bstate.counters["pair_ms"] = 1e3 * pair;
  bstate.SetLabel(std::to_string(s.mx) + "x" + std::to_string(s.my));
}

void BM_FftPair(benchmark::State& bstate) {
  const Size s = sizes[bstate.range(0)];
  auto engine = padded_engine(s);
  for (auto _ : bstate) fft_pair(*engine);
  bstate.SetLabel(std::to_string(s.mx) + "x" + std::to_string(s.my));
}

void BM_TangentialProduct(benchmark::State& bstate) {
  const Size s = sizes[bstate.range(0)];
  const Grid g = grid_of(s);
  const auto xx = elastic::make_kernel(Component::xx, g, steel());
  const auto xy = elastic::make_kernel(Component::xy, g, steel());
  const auto yy = elastic::make_kernel(Component::yy, g, steel());
  elastic::BlockConvolution a(2, 2, {&xx, &xy, &xy, &yy}, FftBackendKind::Default);
  const std::size_t n = g.size();
  const auto px = random_field(n, 2), py = random_field(n, 3);
  std::vector<double> ux(n), uy(n);
  const double* in[2] = {px.data(), py.data()};
  double* out[2] = {ux.data(), uy.data()};
  run_in_pairs(bstate, s, [&] {
    a.apply(in, out);
    benchmark::DoNotOptimize(ux[0]);
  });
}

void BM_TangentialPreconditioner(benchmark::State& bstate) {
  const Size s = sizes[bstate.range(0)];
  const Grid g = grid_of(s);
  const auto xx = elastic::make_kernel(Component::xx, g, steel());
  const auto xy = elastic::make_kernel(Component::xy, g, steel());
  const auto yy = elastic::make_kernel(Component::yy, g, steel());
  tangential::TangentialPreconditioner m(xx, xy, yy, FftBackendKind::Default);
  const std::size_t n = g.size();
  const auto rx = random_field(n, 4), ry = random_field(n, 5);
  std::vector<double> zx(n), zy(n);
  run_in_pairs(bstate, s, [&] {
    m.apply(rx.data(), ry.data(), zx.data(), zy.data());
    benchmark::DoNotOptimize(zx[0]);
  });
}

}  // namespace

BENCHMARK(BM_FftPair)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TangentialProduct)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TangentialPreconditioner)->DenseRange(0, 3)->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
