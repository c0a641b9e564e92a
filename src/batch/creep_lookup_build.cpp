#include "batch/creep_lookup_build.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "batch/parallel.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/version.hpp"

namespace rollcontact::batch {

namespace {

constexpr double kC = 9.0;  // √(ab) of every node [mm] (any value: the table is normalised)

std::string method_name(const TableSettings& s) {
  return table_method_name(s.method);
}

struct NodeIndex {
  std::size_t ab, ksi, eta, phi;
};

NodeIndex node_of(const CreepLookupAxes& ax, std::size_t flat) {
  NodeIndex n{};
  n.phi = flat % ax.phi.size();
  flat /= ax.phi.size();
  n.eta = flat % ax.eta.size();
  flat /= ax.eta.size();
  n.ksi = flat % ax.ksi.size();
  n.ab = flat / ax.ksi.size();
  return n;
}

}  // namespace

CreepLookupAxes default_lookup_axes() {
  CreepLookupAxes ax;
  ax.a_over_b = {0.2, 0.25, 0.3, 0.4, 0.5, 0.6, 0.7, 0.85, 1.0,
                 1.2, 1.4,  1.7, 2.0, 2.5, 3.0, 4.0, 5.0};
  // Creep forces saturate near ξ̃ = 3/C11 ≈ 0.7 (Johnson's approximation) and bend most near
  // zero; spin saturates more slowly.
  const std::vector<double> half{0.01, 0.025, 0.05, 0.08, 0.12, 0.17,
                                 0.23, 0.3,   0.4,  0.55, 0.75, 1.0};
  std::vector<double> creep;
  for (auto it = half.rbegin(); it != half.rend(); ++it) creep.push_back(-*it);
  creep.push_back(0.0);
  creep.insert(creep.end(), half.begin(), half.end());
  ax.ksi = ax.eta = creep;
  const std::vector<double> spin{0.03, 0.08, 0.15, 0.25, 0.4, 0.6, 0.9, 1.3, 2.0, 3.0};
  for (auto it = spin.rbegin(); it != spin.rend(); ++it) ax.phi.push_back(-*it);
  ax.phi.push_back(0.0);
  ax.phi.insert(ax.phi.end(), spin.begin(), spin.end());
  return ax;
}

CreepLookupAxes coarse_lookup_axes() {
  const std::vector<double> creep{-1.0, -0.3, -0.1, 0.0, 0.1, 0.3, 1.0};
  return {{0.5, 1.0, 2.0}, creep, creep, {-1.0, 0.0, 1.0}};
}

model::PatchProblem lookup_problem(double a_over_b, double ksi_n, double eta_n, double phi_n,
                                   const TableSettings& s) {
  TableCase tc;
  tc.a_over_b = a_over_b;
  tc.a = kC * std::sqrt(a_over_b);
  tc.b = kC / std::sqrt(a_over_b);
  model::PatchProblem p = table_problem(tc, s);
  const double unit = table_mu * table_fn / (table_g * kC * kC);  // ξ per unit of ξ̃
  p.tangential.creepage = {ksi_n * unit, eta_n * unit, phi_n * unit / kC};
  return p;
}

CreepLookupValue solve_lookup_node(double a_over_b, double ksi_n, double eta_n, double phi_n,
                                   const TableSettings& s, PatchSolver& solver) {
  const Solution sol = solver.solve(lookup_problem(a_over_b, ksi_n, eta_n, phi_n, s));
  if (!sol.solver.converged)
    throw SolverError(fmt::format("lookup node a/b {:g}, ksi {:g}, eta {:g}, phi {:g}: {}",
                                  a_over_b, ksi_n, eta_n, phi_n, sol.solver.message));
  const double mufn = table_mu * sol.totals.fn;
  return {sol.totals.fx / mufn, sol.totals.fy / mufn, sol.totals.mz / (mufn * kC)};
}

CreepLookupTable build_creep_lookup(const CreepLookupAxes& axes, const TableSettings& s,
                                    int threads, Distribution* distribution,
                                    const std::function<void(std::size_t)>& progress) {
  check_table_settings(s);
  const std::size_t n = axes.a_over_b.size() * axes.ksi.size() * axes.eta.size() * axes.phi.size();
  auto node = [&](std::size_t i, PatchSolver& solver) {
    const NodeIndex k = node_of(axes, i);
    return solve_lookup_node(axes.a_over_b[k.ab], axes.ksi[k.ksi], axes.eta[k.eta], axes.phi[k.phi],
                             s, solver);
  };
  std::vector<CreepLookupValue> values(n);
  if (distribution != nullptr && distribution->size() > 1) {
    PatchSolver solver;
    const std::vector<std::string> blobs =
        distribution->map_gather(n, default_chunk(n, distribution->size()), [&](std::size_t i) {
          const CreepLookupValue v = node(i, solver);
          return std::string(reinterpret_cast<const char*>(&v), sizeof v);
        });
    if (!distribution->is_root()) return {};
    for (std::size_t i = 0; i < n; ++i) std::memcpy(&values[i], blobs[i].data(), sizeof values[i]);
  } else {
    std::vector<PatchSolver> solvers(worker_count(n, threads));
    // Cyclic: neighbouring nodes (same a/b, the same grid and operators) on different workers.
    parallel_for(
        n, {threads, Schedule::Cyclic},
        [&](std::size_t worker, std::size_t i) { values[i] = node(i, solvers[worker]); }, progress);
  }
  CreepLookupInfo info;
  info.method = method_name(s);
  info.mx = s.mx;
  info.poisson_ratio = table_nu;
  info.software = std::string("rollcontact ") + version_string;
  return CreepLookupTable(axes, std::move(values), std::move(info));
}

LookupAccuracy held_back_accuracy(const CreepLookupTable& table, const TableSettings& s,
                                  std::size_t points, unsigned seed, int threads) {
  const CreepLookupAxes& ax = table.axes();
  // A small linear congruential generator: the same points on every platform.
  std::uint64_t state = 0x9E3779B97F4A7C15ULL ^ seed;
  auto uniform = [&](const std::vector<double>& axis) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = static_cast<double>(state >> 11) * 0x1.0p-53;
    return axis.front() + u * (axis.back() - axis.front());
  };
  struct Point {
    double ab, ksi, eta, phi;
  };
  std::vector<Point> pts(points);
  for (Point& p : pts)
    p = {uniform(ax.a_over_b), uniform(ax.ksi), uniform(ax.eta), uniform(ax.phi)};
  std::vector<CreepLookupValue> exact(points);
  std::vector<PatchSolver> solvers(worker_count(points, threads));
  parallel_for(points, {threads, Schedule::Dynamic}, [&](std::size_t worker, std::size_t i) {
    exact[i] = solve_lookup_node(pts[i].ab, pts[i].ksi, pts[i].eta, pts[i].phi, s, solvers[worker]);
  });
  LookupAccuracy acc;
  acc.points = points;
  double sum = 0.0;
  for (std::size_t i = 0; i < points; ++i) {
    const CreepLookupValue v = table.evaluate(pts[i].ab, pts[i].ksi, pts[i].eta, pts[i].phi);
    const double df = std::hypot(v.fx - exact[i].fx, v.fy - exact[i].fy);
    acc.max_force_error = std::max(acc.max_force_error, df);
    acc.max_moment_error = std::max(acc.max_moment_error, std::abs(v.mz - exact[i].mz));
    sum += df * df;
  }
  acc.rms_force_error = points > 0 ? std::sqrt(sum / static_cast<double>(points)) : 0.0;
  return acc;
}

}  // namespace rollcontact::batch
