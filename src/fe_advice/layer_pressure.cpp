// The pressure error of a penalty compliance: the same frictionless normal contact solved with
// rollcontact's exact normal solver with and without a compressible interfacial layer (B=1,
// FLXZ = L), and the layer's Winkler limit in closed form.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "fe_advice/value_checks.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/fe_advice.hpp"
#include "rollcontact/solve.hpp"

namespace rollcontact::fe_advice {

namespace {

constexpr double kTolerance = 1e-8;   // of the normal CG: pmax to far better than 0.1 %
constexpr double kMargin = 1.15;      // grid half-widths over the estimated interpenetration
constexpr double kEnlargement = 1.4;  // when the contact reached the grid's border
constexpr int kMaxEnlargements = 6;
constexpr double kMaxElements = 4.0e6;  // beyond, a finer grid step than the case needs

/// Combined modulus E* of two equal bodies: 1/E* = 2(1 − ν²)/E [N/mm²].
double combined_modulus_N_mm2(const FeMaterial& m) {
  return m.young_N_mm2 / (2.0 * (1.0 - m.poisson * m.poisson));
}

/// An upper estimate of the approach: the Hertzian one of the equivalent sphere
/// (R = 1/(2√(AB))) plus the Winkler one of the layer alone — two compliances in series.
double approach_estimate_mm(const NormalContactCase& c, double compliance) {
  const double radius = 0.5 / std::sqrt(c.curvature_x_1_mm * c.curvature_y_1_mm);
  const double a =
      std::cbrt(3.0 * c.normal_force_N * radius / (4.0 * combined_modulus_N_mm2(c.material)));
  const double hertz = a * a / radius;
  return hertz + (compliance > 0.0 ? winkler_paraboloid(c, compliance).approach_mm : 0.0);
}

/// The module-3 problem: an odd number of elements per side, so that an element sits at the
/// gap's minimum (where the pressure peaks), and half-widths `xh`, `yh`.
model::PatchProblem normal_problem(const NormalContactCase& c, double compliance, double xh,
                                   double yh) {
  const double d = c.grid_step_mm;
  const int mx = 2 * static_cast<int>(std::ceil(xh / d)) + 1;
  const int my = 2 * static_cast<int>(std::ceil(yh / d)) + 1;
  if (static_cast<double>(mx) * my > kMaxElements)
    throw InvalidValueError(
        "contact.grid_step_mm",
        fmt::format(" = {}: gives {} × {} elements; use a coarser grid", d, mx, my));
  model::PatchProblem p;
  p.potential.ipotcn = 1;
  p.potential.mx = mx;
  p.potential.my = my;
  p.potential.values = {-0.5 * mx * d, -0.5 * my * d, d, d};
  p.gap.ibase = 1;
  p.gap.iplan = 1;
  p.gap.coeffs = {c.curvature_x_1_mm, 0.0, c.curvature_y_1_mm, 0.0, 0.0, 0.0};
  const double g = c.material.young_N_mm2 / (2.0 * (1.0 + c.material.poisson));
  p.bodies.body1 = p.bodies.body2 = {c.material.poisson, g};
  p.bodies.normal_layer_flexibility_mm3_N = compliance;
  p.normal.kind = model::NormalLoadKind::Force;
  p.normal.force_N = c.normal_force_N;
  p.tangential.kind = model::TangentialKind::None;
  p.solver.tolerance = kTolerance;
  return p;
}

/// Whether any element of the grid's outer ring carries pressure.
bool touches_border(const Solution& s) {
  const Grid& g = s.grid;
  for (int iy = 0; iy < g.my; ++iy)
    for (int ix = 0; ix < g.mx; ++ix) {
      const bool border = ix == 0 || iy == 0 || ix == g.mx - 1 || iy == g.my - 1;
      if (border && s.state[g.index(ix, iy)] != ElementState::Exterior) return true;
    }
  return false;
}

NormalContactResult solve_one(PatchSolver& solver, const NormalContactCase& c, double compliance) {
  const double delta = approach_estimate_mm(c, compliance);
  double xh = kMargin * std::sqrt(delta / c.curvature_x_1_mm);
  double yh = kMargin * std::sqrt(delta / c.curvature_y_1_mm);
  for (int attempt = 0;; ++attempt) {
    const Solution s = solver.solve(normal_problem(c, compliance, xh, yh));
    if (!s.solver.converged)
      throw SolverError(
          fmt::format("fe-advice: the normal contact with layer compliance {} mm³/N "
                      "did not converge: {}",
                      compliance, s.solver.message));
    if (!touches_border(s) || attempt == kMaxEnlargements) {
      if (touches_border(s))
        throw SolverError("fe-advice: the contact area still reaches the grid's border");
      return {compliance,   s.totals.pmax,     s.totals.contact_area,
              s.totals.pen, s.statistics.ncon, true};
    }
    xh *= kEnlargement;
    yh *= kEnlargement;
  }
}

}  // namespace

void check_contact_case(const NormalContactCase& contact) {
  detail::require_positive("contact.normal_force_N", contact.normal_force_N);
  detail::require_positive("contact.curvature_x_1_mm", contact.curvature_x_1_mm);
  detail::require_positive("contact.curvature_y_1_mm", contact.curvature_y_1_mm);
  detail::require_positive("contact.grid_step_mm", contact.grid_step_mm);
  check_material(contact.material);
}

std::vector<NormalContactResult> solve_normal_contacts(
    const NormalContactCase& contact, std::span<const double> layer_compliances_mm3_N) {
  check_contact_case(contact);
  for (const double l : layer_compliances_mm3_N)
    detail::require_non_negative("layer_compliance_mm3_N", l);
  PatchSolver solver;  // one for all: the influence operators of a grid are reused
  std::vector<NormalContactResult> results;
  results.reserve(layer_compliances_mm3_N.size());
  for (const double l : layer_compliances_mm3_N) results.push_back(solve_one(solver, contact, l));
  return results;
}

NormalContactResult winkler_paraboloid(const NormalContactCase& contact,
                                       double layer_compliance_mm3_N) {
  check_contact_case(contact);
  detail::require_positive("layer_compliance_mm3_N", layer_compliance_mm3_N);
  const double l = layer_compliance_mm3_N;
  const double root_ab = std::sqrt(contact.curvature_x_1_mm * contact.curvature_y_1_mm);
  // F = ∫(δ − h)/L dA over the ellipse h < δ of area πδ/√(AB): F = πδ²/(2L√(AB)).
  const double delta = std::sqrt(2.0 * l * root_ab * contact.normal_force_N / std::numbers::pi);
  return {l, delta / l, std::numbers::pi * delta / root_ab, delta, 0, true};
}

}  // namespace rollcontact::fe_advice
