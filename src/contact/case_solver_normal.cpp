// CaseSolver, the normal problem: NormCG on a box of the grid or the whole grid, prescribed
// pressures, KPEC and ANALYN.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>

#include "contact/case_solver.hpp"
#include "contact/nested_starts.hpp"
#include "geometry/discretisation.hpp"
#include "geometry/hertz.hpp"
#include "normal/active_set_solver.hpp"
#include "rollcontact/errors.hpp"
#include "simplified/approximate_normal.hpp"
#include "simplified/prescribed_pressure.hpp"

namespace rollcontact::contact {

namespace {

/// The normal solve's box (CaseSolver::normal_box). Measured (instructions, right 10 kN 0.5 mm
/// force sweep): 0.9 and 0.97 equal, 0.75 +1 %.
constexpr double max_normal_box_fraction = 0.9;

}  // namespace

void CaseSolver::solve_normal(const Field& px, const Field& py) {
  const std::size_t n = grid_.size();
  const bool force_given = problem_.normal.kind == model::NormalLoadKind::Force;
  const double load_value = force_given ? problem_.normal.force_N : problem_.normal.approach_mm;
  if (force_given && !(load_value > 0.0))
    throw ProblemError(fmt::format("normal force FN = {} must be positive", load_value));
  NormalOperators& ops = st_.operators.normal(grid_, sol_.material, interaction_);

  // h* = h + u_n(p_t): the normal displacement due to the current tangential tractions (K ≠ 0).
  Field h_star = sol_.h;
  if (coupled_ && tops_ != nullptr) {
    Field un_t(n);
    const double* in[2] = {px.data(), py.data()};
    double* out[1] = {un_t.data()};
    tops_->nt->apply(in, out);
    for (std::size_t i = 0; i < n; ++i)
      if (h_star[i] < geometry::excluded_distance) h_star[i] += un_t[i];
  }

  // The problem the last normal solve of this sequence had (a full solve at the vertical-force
  // iteration's last normal estimate): its answer.
  const auto& last = st_.last_normal;
  const CombinedMaterial& mat = sol_.material;
  if (problem_.sequence.normal_from_previous && sol_.pn.empty() && last &&
      last->eps <= problem_.solver.tolerance && last->force_given == force_given &&
      last->load == load_value && last->same_operator(grid_, mat) && !interaction_ &&
      !mat.viscoelastic() && !mat.table && last->h == h_star) {
    sol_.pn = last->pn;
    normal_un_ = last->un;
    sol_.totals.pen = last->pen;
    sol_.solver.normal_residual = 0.0;
    return;
  }

  // Starting pressure: the current one in an outer loop, else the previous case's when asked
  // for, else the Hertz solution for Hertzian geometries (physics.md §7.1), else the coarse-grid
  // or geometric estimate.
  const Field* initial = nullptr;
  const Field* initial_un = nullptr;  // A·initial when known (no starting product)
  if (!sol_.pn.empty()) {
    initial = &sol_.pn;
  } else if (problem_.sequence.normal_from_previous && prev_.present &&
             std::any_of(latest_pn_.begin(), latest_pn_.end(), [](double v) { return v > 0.0; })) {
    initial = &latest_pn_;
    // The last solve's pressure on the same grid, unmoved (an iterate of the vertical-force
    // iteration a fraction of an element away): its displacement came with it.
    if (latest_is_last_normal_) initial_un = &last->un;
  } else if (problem_.sequence.normal_from_previous && prev_.present &&
             std::any_of(prev_.pn.begin(), prev_.pn.end(), [](double v) { return v > 0.0; })) {
    initial = &prev_.pn;
  }

  const normal::NormalLoad load =
      force_given ? normal::NormalLoad::Force : normal::NormalLoad::Approach;
  normal::NormalResult r;
  if (sol_.material.viscoelastic()) {
    // Viscoelastic rolling (M=1): A is not symmetric, NormCG does not apply
    // (active_set_solver.hpp).
    const Field start = initial == nullptr ? hertz_start(grid_) : Field{};
    if (!start.empty()) initial = &start;
    normal::ActiveSetNormalSolver solver(grid_, *ops.product);
    r = solver.solve(h_star, load, load_value, normal_settings(), initial, mat.nu, mat.g);
  } else {
    r = solve_normal_cg(h_star, load, load_value, initial, initial_un, ops);
  }
  st_.last_normal.reset();
  if (r.converged && !sol_.material.viscoelastic() && !interaction_ && !sol_.material.table) {
    PatchSolver::Impl::NormalAnswer& a = st_.last_normal.emplace();
    a.grid = grid_;
    a.h = h_star;
    a.pn = r.pn;
    a.un = r.un;
    a.force_given = force_given;
    a.load = load_value;
    a.material = sol_.material;
    a.pen = r.pen;
    a.eps = normal_settings().eps;
  }
  if (!sol_.material.viscoelastic()) normal_un_ = r.un;
  sol_.pn = std::move(r.pn);
  sol_.totals.pen = r.pen;
  sol_.solver.normal_iterations += r.iterations;
  sol_.solver.normal_active_set_changes += r.set_changes;
  sol_.solver.normal_products += r.products;
  sol_.solver.normal_iteration_seconds += r.iteration_seconds;
  sol_.solver.normal_residual = r.residual;
  if (!r.converged) {
    sol_.solver.converged = false;
    sol_.solver.message = r.message;
  }
}

Field CaseSolver::hertz_start(const Grid& grid) const {
  if (!sol_.hertz.present) return {};
  Field start(grid.size(), 0.0);
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix)
      start[grid.index(ix, iy)] =
          geometry::hertz_pressure(sol_.hertz, grid.x_centre(ix), grid.y_centre(iy));
  if (std::none_of(start.begin(), start.end(), [](double v) { return v > 0.0; })) return {};
  return start;
}

normal::NormalSettings CaseSolver::normal_settings() const {
  normal::NormalSettings settings;
  // At the case's tolerance also in a rough solve: its pressure is a sample of the
  // vertical-force iteration's normal estimates (wheelrail/vertical_force.hpp).
  settings.eps = problem_.solver.tolerance;
  settings.max_iterations = problem_.solver.max_inner_iterations;
  return settings;
}

std::optional<contact::ContactBox> CaseSolver::normal_box(const Field& h, double pen,
                                                          const Field* initial) const {
  const Grid& g = grid_;
  // Where h ≥ PEN the gap h − PEN + A·p stays open whatever p ≥ 0: the contact lies in the
  // interpenetration. Wheel/rail grids hug that, but the contact covers a third to a half of
  // it (a flat lateral gap), and a starting pressure (an iterate's, the previous case's) tells
  // where: the box around its support (contact_box adds a free element each side and rounds
  // up), to be checked afterwards. Wider margins measured: more products, as few restarts.
  int ix_lo = g.mx, ix_hi = -1, iy_lo = g.my, iy_hi = -1;
  if (initial != nullptr)
    for (int iy = 0; iy < g.my; ++iy)
      for (int ix = 0; ix < g.mx; ++ix)
        if ((*initial)[g.index(ix, iy)] > 0.0) {
          ix_lo = std::min(ix_lo, ix);
          ix_hi = std::max(ix_hi, ix);
          iy_lo = std::min(iy_lo, iy);
          iy_hi = std::max(iy_hi, iy);
        }
  const bool speculative = ix_hi >= 0;
  std::vector<char> inside(h.size(), 0);
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix) {
      const bool near_start =
          !speculative || (ix >= ix_lo && ix <= ix_hi && iy >= iy_lo && iy <= iy_hi);
      inside[g.index(ix, iy)] = near_start && h[g.index(ix, iy)] < pen;
    }
  return contact::contact_box(g, inside, max_normal_box_fraction);
}

normal::NormalResult CaseSolver::solve_normal_cg(const Field& h, normal::NormalLoad load,
                                                 double value, const Field* initial,
                                                 const Field* initial_un, NormalOperators& ops) {
  const CombinedMaterial& mat = sol_.material;
  const normal::NormalSettings settings = normal_settings();
  // With the approach given on a half-space whose influence coefficients are positive the
  // problem on a box that holds the contact is the same problem, with FFT products on the box
  // only (contact/contact_box.hpp). Not for a file's coefficients (no sign known) or attenuated
  // parts (IPLAN=4, not translation invariant).
  std::optional<contact::ContactBox> box;
  if (load == normal::NormalLoad::Approach && !interaction_ && !mat.table)
    box = normal_box(h, value, initial);
  const Grid& grid = box ? box->grid : grid_;
  const Field h_box = box ? contact::restrict_to_box(h, grid_, *box) : Field{};
  const Field& hb = box ? h_box : h;

  Field initial_box, initial_un_box, start;
  if (box && initial != nullptr) {
    // A displacement on the box is the whole pressure's only when the box holds all of it.
    const bool whole = initial_un != nullptr && contact::zero_outside(*initial, grid_, *box);
    if (whole) initial_un_box = contact::restrict_to_box(*initial_un, grid_, *box);
    initial_un = whole ? &initial_un_box : nullptr;
    initial_box = contact::restrict_to_box(*initial, grid_, *box);
    initial = &initial_box;
  }
  if (initial == nullptr) {
    start = hertz_start(grid);
    if (!start.empty()) initial = &start;
  }
  if (initial == nullptr) {
    int coarse_iterations = 0;
    start = coarse_grid_start(st_, 1, grid, hb, load, value, mat, settings, coarse_iterations);
    sol_.solver.normal_coarse_iterations += coarse_iterations;
    if (!start.empty()) initial = &start;
  }

  NormalOperators& bops = box ? st_.operators.normal(grid, mat) : ops;
  normal::NormalSolver solver(grid, *bops.product, bops.kernel, *bops.preconditioner,
                              bops.interaction.get());
  normal::NormalResult r =
      solver.solve(hb, load, value, settings, initial, mat.nu, mat.g, initial_un);
  if (!box) return r;

  // On the whole grid: the pressure, and its displacement (one product) for the outputs and
  // for the check that the contact indeed lies in the box.
  Field pn = contact::expand_from_box(r.pn, grid_, *box, 0.0);
  Field un(grid_.size());
  ops.product->apply(pn.data(), un.data());
  ++r.products;
  bool holds = true;
  for (int iy = 0; iy < grid_.my && holds; ++iy)
    for (int ix = 0; ix < grid_.mx && holds; ++ix) {
      const std::size_t i = grid_.index(ix, iy);
      holds = box->contains(ix, iy) || h[i] + un[i] >= value;
    }
  if (!holds) {
    // The contact reaches beyond the starting pressure's box (around the interpenetration only
    // by rounding): on the whole grid, from here.
    normal::NormalSolver full(grid_, *ops.product, ops.kernel, *ops.preconditioner,
                              ops.interaction.get());
    normal::NormalResult again = full.solve(h, load, value, settings, &pn, mat.nu, mat.g, &un);
    again.iterations += r.iterations;
    again.set_changes += r.set_changes;
    again.products += r.products;
    again.iteration_seconds += r.iteration_seconds;
    return again;
  }
  r.pn = std::move(pn);
  r.un = std::move(un);
  return r;
}

void CaseSolver::set_prescribed_pressure() {
  const model::PressureModel model = problem_.normal.pressure;
  if (model == model::PressureModel::Kpec || model == model::PressureModel::Analyn) {
    set_approximate_pressure(model == model::PressureModel::Kpec);
    return;
  }
  const HertzReport& hz = sol_.hertz;
  if (model == model::PressureModel::Sdec) {
    const auto& v = problem_.potential.values;  // AA BNEG BPOS SCALE
    if (problem_.potential.ipotcn != -6)
      throw ProblemError("SDEC pressures (B=4) need the SDEC potential contact (IPOTCN = -6)");
    sol_.pn = simplified::sdec_pressure(grid_, v[0], v[1], v[2], hz.fn);
    sol_.totals.pen = hz.pen;  // of the mean ellipse (a, b), as for B=2, 3
    return;
  }
  const bool elliptic = problem_.normal.pressure == model::PressureModel::EllipticHertzian;
  if (!hz.present)
    throw ProblemError(
        fmt::format("prescribed pressures B={} need a Hertzian potential contact (IPOTCN < 0)",
                    elliptic ? 2 : 3));
  const auto shape =
      elliptic ? simplified::PressureShape::Elliptic : simplified::PressureShape::Parabolic;
  sol_.pn = simplified::prescribed_pressure(grid_, hz, shape, hz.fn);
  sol_.totals.pen = hz.two_dimensional ? 0.0 : hz.pen;  // 2-D Hertz has no approach
}

void CaseSolver::set_approximate_pressure(bool kpec) {
  const char* name = kpec ? "KPEC (B=5)" : "ANALYN (B=6)";
  if (problem_.normal.kind != model::NormalLoadKind::Approach)
    throw ProblemError(fmt::format("{} needs a prescribed approach (N=0)", name));
  if (sol_.hertz.present)
    throw ProblemError(fmt::format("{} needs a non-Hertzian potential contact (IPOTCN > 0)", name));
  Field h_total = sol_.h;
  for (double& v : h_total)
    if (v < geometry::excluded_distance) v -= problem_.normal.approach_mm;
  simplified::ApproximateNormal r =
      kpec ? simplified::kpec_pressure(grid_, h_total, sol_.material,
                                       st_.operators.normal_kernel(grid_, sol_.material))
           : simplified::analyn_pressure(grid_, h_total, sol_.material);
  sol_.pn = std::move(r.pn);
  sol_.solver.kpec_rows_beyond_interpenetration = r.rows_beyond_interpenetration;
  approximate_ = true;
  sol_.totals.pen = problem_.normal.approach_mm;
}

double CaseSolver::total_normal_force() const {
  if (prescribed_ && !approximate_) return sol_.hertz.fn;
  double fn = 0.0;
  for (double v : sol_.pn) fn += v;
  return fn * grid_.element_area();
}
}  // namespace rollcontact::contact
