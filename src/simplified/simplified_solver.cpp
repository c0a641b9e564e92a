// The simplified tangential problem of one case (spec/physics.md §11).

#include "simplified/simplified_solver.hpp"

#include <cmath>

#include "rollcontact/errors.hpp"
#include "simplified/fastrip.hpp"
#include "tangential/kinematics.hpp"

namespace rollcontact::simplified {

SimplifiedModel simplified_model(const model::PatchProblem& problem) {
  using model::TangentialCompliance;
  const TangentialCompliance c = problem.bodies.compliance;
  const model::SimplifiedParameters& sp = problem.bodies.simplified;
  SimplifiedModel m;
  m.m = c == TangentialCompliance::FastsimOneFlexibility ? 2
        : c == TangentialCompliance::FaStrip             ? 5
                                                         : 3;
  if (m.m == 2) {
    m.flx = sp.flexibility_mm3_N;
    if (!(m.flx > 0.0)) throw ProblemError("M=2: the flexibility FLX must be positive");
  }
  m.slope = {sp.k0, sp.alpha_inf, sp.beta};
  if (!(m.slope.k0 > 0.0)) throw ProblemError("Modified Fastsim: K0_MF must be positive");
  // Module 3 blends only with prescribed creepages: in the force iteration the creep curve must
  // stay one smooth function of the unknown creepage.
  m.blend = m.m != 2 && problem.tangential.prescribed == model::TangentialPrescribed::Creepages;
  return m;
}

RigidShiftParts rigid_shift_parts(const Grid& grid, const model::PatchProblem& problem,
                                  const EffectiveKinematics& kin, const Creepages& cr) {
  tangential::RigidShift full = tangential::rigid_shift(grid, problem, kin, cr.ksi, cr.eta, cr.phi);
  tangential::RigidShift base = tangential::rigid_shift(grid, problem, kin, cr.ksi, cr.eta, 0.0);
  RigidShiftParts p;
  p.spin_x.resize(grid.size());
  p.spin_y.resize(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    p.spin_x[i] = full.wx[i] - base.wx[i];
    p.spin_y[i] = full.wy[i] - base.wy[i];
  }
  p.wx = std::move(base.wx);
  p.wy = std::move(base.wy);
  return p;
}

namespace {

/// μ of the flexibilities' blending and slope reduction (physics.md §11.2): FSTAT for Coulomb
/// friction, a velocity-dependent law's μ_s at the absolute rigid slip velocity V·√(ξ² + η²)
/// (δq = δx in steady rolling: V = δx/δt).
double flexibility_mu(const SimplifiedCase& c) {
  if (c.velocity == nullptr) return c.mu;
  const double speed = std::hypot(c.creepages.ksi, c.creepages.eta) * c.grid.dx / c.velocity->dt_s;
  return c.velocity->law->coefficient_at(speed);
}

}  // namespace

SimplifiedOutcome solve_simplified(const SimplifiedCase& c) {
  const Ellipse& e = c.ellipse;
  if (!(e.a > 0.0) || !(e.b > 0.0) || !std::isfinite(e.a / e.b))
    throw ProblemError("simplified theory: the contact patch has no extent (ellipse a, b = 0)");
  SimplifiedOutcome out;
  out.coefficients = kalker_coefficients(e.a / e.b, c.nu);
  if (c.model.m == 2) {
    out.flex = {c.model.flx, c.model.flx, c.model.flx};
  } else {
    out.flex = kalker_flexibilities(e, out.coefficients, c.g);
    if (c.model.blend)
      out.flex = blend_flexibilities(out.flex, e, out.coefficients, c.g, flexibility_mu(c), c.fn,
                                     c.creepages);
  }
  // The slope reduction and the strip theory describe the actual contact patch: its equivalent
  // ellipse (for IPOTCN < 0 close to, but not equal to, the Hertz ellipse).
  const Ellipse eq = equivalent_ellipse(c.grid, c.pn);
  const KalkerCoefficients eq_coefficients =
      eq.a > 0.0 && eq.b > 0.0 ? kalker_coefficients(eq.a / eq.b, c.nu) : out.coefficients;
  out.k_eff = slope_reduction_factor(c.model.slope, eq, eq_coefficients.c11, c.g, flexibility_mu(c),
                                     c.fn, c.creepages);
  const Flexibilities eff{out.flex.l1 / out.k_eff, out.flex.l2 / out.k_eff,
                          out.flex.l3 / out.k_eff};

  // Spin acts through the flexibility L3; Fastsim's u = L1·p_x, L2·p_y, so the spin part of the
  // rigid shift is scaled by L1/L3 and L2/L3 (with M=2 the factors are 1).
  const std::size_t n = c.grid.size();
  const RigidShiftParts& w = *c.shift;
  std::vector<double> wx(n), wy(n);
  const double fx = out.flex.l1 / out.flex.l3, fy = out.flex.l2 / out.flex.l3;
  for (std::size_t i = 0; i < n; ++i) {
    wx[i] = w.wx[i] + fx * w.spin_x[i];
    wy[i] = w.wy[i] + fy * w.spin_y[i];
  }

  // The law's slip velocity per element: the rigid slip, spin unscaled, over the step.
  std::vector<double> rigid_speed;
  if (c.velocity != nullptr) {
    rigid_speed.resize(n);
    for (std::size_t i = 0; i < n; ++i)
      rigid_speed[i] = std::hypot(w.wx[i] + w.spin_x[i], w.wy[i] + w.spin_y[i]) / c.velocity->dt_s;
  }
  FastsimInput in;
  in.grid = c.grid;
  in.rigid_speed = rigid_speed;
  in.pn = c.pn;
  in.mu = c.mu;
  in.velocity = c.velocity;
  in.mu_prev = c.mu_prev;
  in.wx = wx;
  in.wy = wy;
  in.flex = eff;
  in.steady = c.steady;
  in.chi = c.chi;
  in.ux_prev = c.ux_prev;
  in.uy_prev = c.uy_prev;
  out.fields = fastsim(in);

  if (c.model.m == 5) {
    FastripInput fr;
    fr.grid = c.grid;
    fr.pn = c.pn;
    fr.mu = c.mu;
    fr.ellipse = eq;
    fr.coefficients = eq_coefficients;
    fr.g = c.g;
    fr.nu = c.nu;
    fr.fn = c.fn;
    fr.creepages = c.creepages;
    fr.chi = c.chi;
    fr.flex = eff;
    fastrip_correction(fr, out.fields);
  }
  return out;
}

}  // namespace rollcontact::simplified
