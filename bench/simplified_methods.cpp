// Benchmark of the simplified theory (spec/physics.md §11): one steady-rolling case with Modified
// Fastsim (M=3) and with Modified FaStrip (M=5) on 11×11 and 25×25 Hertzian grids, elliptic
// pressure (B=2), creepages and spin as in fastsim.inp (a = 8, b = 4 mm, FN = 82 kN).
//
// BM_SimplifiedCase times solve() for the whole case (Hertz, grid, pressure, flexibilities,
// Fastsim/FaStrip, totals) — what a multibody code pays per contact patch and time step.
// BM_SimplifiedKernel times only the tangential part on a prepared pressure.

#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <string>
#include <vector>

#include "rollcontact/solve.hpp"
#include "simplified/prescribed_pressure.hpp"
#include "simplified/simplified_solver.hpp"

namespace {

using namespace rollcontact;

Problem fastsim_problem(int method, int m) {
  Problem p;
  p.digits.p = 2;
  p.digits.b = 2;
  p.digits.t = 3;
  p.digits.n = 1;
  p.digits.m = method;
  p.digits.o = 1;
  p.kinematics.fn = 82000.0;
  p.kinematics.cksi = 0.0;
  p.kinematics.ceta = -6.25e-4;
  p.kinematics.cphi = 6.25e-4;
  p.kinematics.dq = 16.0 / m;
  p.kinematics.veloc = 30000.0;
  p.friction.fstat = p.friction.fkin = 0.3;
  p.materials.poiss1 = p.materials.poiss2 = 0.28;
  p.materials.gg1 = p.materials.gg2 = 82000.0;
  p.materials.model_params = {1.0, 1.0, 1.0, 0.0};  // K0_MF ALFAMF BETAMF: original Fastsim
  p.potential.ipotcn = -3;
  p.potential.mx = m;
  p.potential.my = m;
  p.potential.values = {8.0, 4.0, 1.1, 0.0};
  return p;
}

std::string label(int method, int m) {
  return std::string(method == 5 ? "FaStrip " : "Fastsim ") + std::to_string(m) + "x" +
         std::to_string(m);
}

void BM_SimplifiedCase(benchmark::State& bstate) {
  const int method = static_cast<int>(bstate.range(0)), m = static_cast<int>(bstate.range(1));
  const Problem problem = fastsim_problem(method, m);
  State state;
  Solution sol = solve(problem, state);
  for (auto _ : bstate) {
    sol = solve(problem, state);
    // A const operand: benchmark 1.7's DoNotOptimize(T&) ("+r,m") can write garbage back into a
    // double with GCC 12 (seen here as FY = 6.95e-310 after the loop).
    const double fy = sol.totals.fy;
    benchmark::DoNotOptimize(fy);
  }
  bstate.counters["ncon"] = sol.statistics.ncon;
  // In the label: the console reporter rounds small counters to 0.
  bstate.SetLabel(label(method, m) +
                  fmt::format(" FY/muFN={:.4f}", sol.totals.fy / (0.3 * sol.totals.fn)));
}

void BM_SimplifiedKernel(benchmark::State& bstate) {
  const int method = static_cast<int>(bstate.range(0)), m = static_cast<int>(bstate.range(1));
  const Problem problem = fastsim_problem(method, m);
  State state;
  const Solution sol = solve(problem, state);  // grid, Hertz and pressure of the case
  simplified::SimplifiedCase c;
  c.grid = sol.grid;
  c.pn = sol.pn;
  c.ellipse = {sol.hertz.aa, sol.hertz.bb};
  c.g = sol.material.g;
  c.nu = sol.material.nu;
  c.mu = 0.3;
  c.fn = problem.kinematics.fn;
  c.model = simplified::simplified_model(problem);
  c.creepages = {problem.kinematics.cksi, problem.kinematics.ceta, problem.kinematics.cphi};
  const simplified::RigidShiftParts shift =
      simplified::rigid_shift_parts(sol.grid, problem, sol.kinematics, c.creepages);
  c.shift = &shift;
  for (auto _ : bstate) {
    simplified::SimplifiedOutcome r = simplified::solve_simplified(c);
    benchmark::DoNotOptimize(r.fields.py.data());
  }
  bstate.SetLabel(label(method, m));
}

// Arguments: method (3 Fastsim, 5 FaStrip), grid size m (m × m elements over 1.1 × the ellipse).
BENCHMARK(BM_SimplifiedCase)->ArgsProduct({{3, 5}, {11, 25}})->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SimplifiedKernel)->ArgsProduct({{3, 5}, {11, 25}})->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
