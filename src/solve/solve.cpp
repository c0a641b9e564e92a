#include "rollcontact/solve.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "elastic/material.hpp"
#include "geometry/discretisation.hpp"
#include "geometry/hertz.hpp"
#include "normal/normal_solver.hpp"
#include "rollcontact/errors.hpp"
#include "solve/state_impl.hpp"

namespace rollcontact {

namespace {

[[noreturn]] void not_supported(const std::string& what) {
  throw NotSupportedError("not supported yet: " + what);
}

}  // namespace

void check_supported(const Problem& problem) {
  const ControlDigits& d = problem.digits;
  if (d.t != 0) not_supported(fmt::format("tangential problem T={}", d.t));
  if (d.b != 0) not_supported(fmt::format("normal method B={}", d.b));
  if (d.m != 0) not_supported(fmt::format("material model M={}", d.m));
  if (d.c == 3 || d.c == 4 || d.c == 9)
    not_supported(fmt::format("influence coefficients C={}", d.c));
  if (d.s != 0) not_supported(fmt::format("subsurface stresses S={}", d.s));
  if (d.h != 0) not_supported(fmt::format("temperature H={}", d.h));
  if (d.e != 0 && d.e != 1) not_supported(fmt::format("extra rigid slip E={}", d.e));
  if (d.v != 0) not_supported(fmt::format("variable friction V={}", d.v));
  if (problem.potential.ipotcn == -6) not_supported("SDEC potential contact IPOTCN=-6");
}

Solution solve(const Problem& problem, State& state) {
  check_supported(problem);
  State::Impl& st = state.impl();
  const Materials& mat = problem.materials;

  Solution sol;
  sol.material = elastic::combine_materials(mat.poiss1, mat.poiss2, mat.gg1, mat.gg2);
  geometry::Discretisation disc = geometry::build_discretisation(problem, sol.material);
  sol.grid = disc.grid;
  sol.hertz = disc.hertz;
  sol.h = std::move(disc.h);

  const Grid& grid = sol.grid;
  const std::size_t n = grid.size();
  const bool force_given = problem.digits.n == 1;
  const double load_value = force_given ? problem.kinematics.fn : problem.kinematics.pen;
  if (force_given && !(load_value > 0.0))
    throw ProblemError(fmt::format("normal force FN = {} must be positive", load_value));

  NormalOperators& ops = st.normal_operators(grid, sol.material);

  // Starting pressure: the Hertz solution for Hertzian geometries (physics.md §7.1), the previous
  // case's pressure on the same grid when asked for (I digit), otherwise the geometric estimate.
  std::vector<double> start;
  const std::vector<double>* initial = nullptr;
  if (problem.digits.i >= 1 && st.previous && st.previous->grid.mx == grid.mx &&
      st.previous->grid.my == grid.my && !st.previous->pn.empty()) {
    start = st.previous->pn;
    initial = &start;
  } else if (sol.hertz.present) {
    start.assign(n, 0.0);
    for (int iy = 0; iy < grid.my; ++iy)
      for (int ix = 0; ix < grid.mx; ++ix)
        start[grid.index(ix, iy)] =
            geometry::hertz_pressure(sol.hertz, grid.x_centre(ix), grid.y_centre(iy));
    if (std::any_of(start.begin(), start.end(), [](double v) { return v > 0.0; })) initial = &start;
  }

  normal::NormalSolver solver(grid, *ops.product, ops.kernel, *ops.preconditioner);
  normal::NormalSettings settings;
  settings.eps = problem.solver.eps;
  settings.max_iterations = problem.solver.maxgs;
  normal::NormalResult nres =
      solver.solve(sol.h, force_given ? normal::NormalLoad::Force : normal::NormalLoad::Approach,
                   load_value, settings, initial, sol.material.nu, sol.material.g);

  sol.pn = std::move(nres.pn);
  sol.un = std::move(nres.un);
  sol.px.assign(n, 0.0);
  sol.py.assign(n, 0.0);
  sol.ux.assign(n, 0.0);
  sol.uy.assign(n, 0.0);
  sol.sx.assign(n, 0.0);
  sol.sy.assign(n, 0.0);
  sol.state.assign(n, ElementState::Exterior);

  Totals& t = sol.totals;
  Statistics& s = sol.statistics;
  s.npot = static_cast<int>(n);
  double energy = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    if (sol.pn[i] > 0.0) {
      // Without a tangential problem every contact element counts as adhesion (CONTACT's '*').
      sol.state[i] = ElementState::Adhesion;
      ++s.ncon;
      t.pmax = std::max(t.pmax, sol.pn[i]);
      energy += sol.pn[i] * sol.un[i];
    }
  }
  s.nadh = s.ncon;
  s.inorm = 1;
  t.fn = nres.fn;
  t.pen = nres.pen;
  t.contact_area = s.ncon * grid.element_area();
  t.elastic_energy = 0.5e-3 * energy * grid.element_area();  // N·mm → J

  sol.solver.converged = nres.converged;
  sol.solver.message = nres.message;
  sol.solver.normal_iterations = nres.iterations;
  sol.solver.normal_active_set_changes = nres.set_changes;
  sol.solver.normal_products = nres.products;
  sol.solver.normal_residual = nres.residual;

  st.previous = sol;
  return sol;
}

}  // namespace rollcontact
