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

model::PatchProblem fastsim_problem(int method, int m) {
  model::PatchProblem p;
  p.normal.pressure = model::PressureModel::EllipticHertzian;
  p.tangential.kind = model::TangentialKind::SteadyRolling;
  p.bodies.compliance = method == 5 ? model::TangentialCompliance::FaStrip
                                    : model::TangentialCompliance::FastsimThreeFlexibilities;
  p.normal.force_N = 82000.0;
  p.tangential.creepage.longitudinal = 0.0;
  p.tangential.creepage.lateral = -6.25e-4;
  p.tangential.creepage.spin_rad_per_mm = 6.25e-4;
  p.rolling.step_mm = 16.0 / m;
  p.rolling.velocity_mm_per_s = 30000.0;
  p.friction = {0.3, 0.3};
  p.bodies.body1 = p.bodies.body2 = {0.28, 82000.0};
  p.bodies.simplified = {0.0, 1.0, 1.0, 1.0};  // k0 = α∞ = β = 1: original Fastsim
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
  const model::PatchProblem problem = fastsim_problem(method, m);
  PatchSolver state;
  Solution sol = state.solve(problem);
  for (auto _ : bstate) {
    sol = state.solve(problem);
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
  const model::PatchProblem problem = fastsim_problem(method, m);
  PatchSolver state;
  const Solution sol = state.solve(problem);  // grid, Hertz and pressure of the case
  simplified::SimplifiedCase c;
  c.grid = sol.grid;
  c.pn = sol.pn;
  c.ellipse = {sol.hertz.aa, sol.hertz.bb};
  c.g = sol.material.g;
  c.nu = sol.material.nu;
  c.mu = 0.3;
  c.fn = problem.normal.force_N;
  c.model = simplified::simplified_model(problem);
  c.creepages = {problem.tangential.creepage.longitudinal, problem.tangential.creepage.lateral,
                 problem.tangential.creepage.spin_rad_per_mm};
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
