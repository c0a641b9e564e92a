// Query cost of creep-force lookup tables (include/rollcontact/creep_lookup.hpp): one evaluation
// at a pseudo-random point of a table with the default grid (223,125 nodes, 5.4 MB of values),
// through the C++ API and through the C interface of librollcontact_cntc.so — what an MBS code
// pays per wheel and time step. Goal: under a microsecond.

#include "rollcontact/creep_lookup.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <filesystem>
#include <vector>

#include "batch/creep_lookup_build.hpp"
#include "rollcontact/creep_lookup.hpp"

namespace {

using namespace rollcontact;

/// The default grid filled with a smooth saturating function (the values do not change the
/// cost of a query).
const CreepLookupTable& table() {
  static const CreepLookupTable t = [] {
    const CreepLookupAxes ax = batch::default_lookup_axes();
    std::vector<CreepLookupValue> v;
    v.reserve(ax.a_over_b.size() * ax.ksi.size() * ax.eta.size() * ax.phi.size());
    for (double ab : ax.a_over_b)
      for (double x : ax.ksi)
        for (double y : ax.eta)
          for (double z : ax.phi)
            v.push_back({-std::tanh(4 * x) / std::sqrt(ab), -std::tanh(4 * y + z), 0.1 * z});
    return CreepLookupTable(ax, std::move(v), {});
  }();
  return t;
}

struct Query {
  double ab, x, y, z;
};

std::vector<Query> queries() {
  std::vector<Query> q(4096);
  unsigned long long s = 12345;
  auto u = [&] {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    return static_cast<double>(s >> 11) * 0x1.0p-53;
  };
  for (Query& e : q) e = {0.2 + 4.8 * u(), 2 * u() - 1, 2 * u() - 1, 6 * u() - 3};
  return q;
}

void BM_LookupEvaluateCpp(benchmark::State& state) {
  const CreepLookupTable& t = table();
  const std::vector<Query> q = queries();
  std::size_t i = 0;
  for (auto _ : state) {
    const Query& e = q[i++ & 4095];
    const CreepLookupValue v = t.evaluate(e.ab, e.x, e.y, e.z);
    benchmark::DoNotOptimize(v);
  }
}
BENCHMARK(BM_LookupEvaluateCpp);

void BM_LookupEvaluateC(benchmark::State& state) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "bench_lookup.h5";
  save_creep_lookup(table(), path);
  rc_creep_lookup* c = rc_creep_lookup_open(path.c_str(), nullptr, 0);
  const std::vector<Query> q = queries();
  std::size_t i = 0;
  double out[3];
  for (auto _ : state) {
    const Query& e = q[i++ & 4095];
    rc_creep_lookup_eval(c, e.ab, e.x, e.y, e.z, out);
    benchmark::DoNotOptimize(out);
  }
  rc_creep_lookup_close(c);
}
BENCHMARK(BM_LookupEvaluateC);

}  // namespace

BENCHMARK_MAIN();
