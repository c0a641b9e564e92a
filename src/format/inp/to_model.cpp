// CaseRecord → model::PatchProblem (spec/inp-format.md §3 for the digits).

#include "format/inp/to_model.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <optional>

#include "format/inp/grid_extent.hpp"
#include "format/inp/influence_file.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

[[noreturn]] void not_supported(const std::string& what) {
  throw NotSupportedError("not supported yet: " + what);
}

model::Bodies bodies_of(const CaseRecord& r) {
  const Materials& m = r.materials;
  model::Bodies b;
  b.body1 = {m.poiss1, m.gg1};
  b.body2 = {m.poiss2, m.gg2};
  const auto& mp = m.model_params;
  switch (r.digits.m) {
    case 2:  // FLX K0_MF ALFAMF BETAMF
      b.compliance = model::TangentialCompliance::FastsimOneFlexibility;
      b.simplified = {mp[0], mp[1], mp[2], mp[3]};
      break;
    case 3:  // K0_MF ALFAMF BETAMF
    case 5:
      b.compliance = r.digits.m == 3 ? model::TangentialCompliance::FastsimThreeFlexibilities
                                     : model::TangentialCompliance::FaStrip;
      b.simplified = {0.0, mp[0], mp[1], mp[2]};
      break;
    case 1:  // FG1 FG2 TC1 TC2: standard linear solids, GG1, GG2 the glassy moduli
      b.compliance = model::TangentialCompliance::ExactHalfSpace;
      b.viscoelastic = true;
      b.viscous1 = {mp[0], mp[2]};
      b.viscous2 = {mp[1], mp[3]};
      break;
    case 4:  // GG3 LAYTHK TAU_C0 K_TAU (TAU_C0 >= 1e10 already stored as 0)
      b.compliance = model::TangentialCompliance::ExactHalfSpace;
      b.has_layer = true;
      b.layer = {mp[0], mp[1], mp[2], mp[3]};
      break;
    default:
      b.compliance = model::TangentialCompliance::ExactHalfSpace;
  }
  return b;
}

// H >= 1: both bodies as conducting half-spaces (H=1 keeps the stored parameters, which the
// readers carry in the record).
model::SurfaceHeat heat_of(const CaseRecord& r) {
  const HeatParameters& h = r.heat;
  model::SurfaceHeat s;
  s.enabled = r.digits.h >= 1;
  s.body1 = {h.bktemp1, h.heatcp1, h.lambda1, h.dens1};
  s.body2 = {h.bktemp2, h.heatcp2, h.lambda2, h.dens2};
  s.plastic_heat_fraction = r.digits.m == 4 ? h.betapl : 0.0;
  return s;
}

model::NormalLoading normal_of(const CaseRecord& r) {
  model::NormalLoading n;
  n.kind = r.digits.n == 1 ? model::NormalLoadKind::Force : model::NormalLoadKind::Approach;
  n.approach_mm = r.kinematics.pen;
  n.force_N = r.kinematics.fn;
  n.pressure = r.digits.b == 2   ? model::PressureModel::EllipticHertzian
               : r.digits.b == 3 ? model::PressureModel::ParabolicHertzian
               : r.digits.b == 4 ? model::PressureModel::Sdec
               : r.digits.b == 5 ? model::PressureModel::Kpec
               : r.digits.b == 6 ? model::PressureModel::Analyn
                                 : model::PressureModel::ExactHalfSpace;
  return n;
}

model::TangentialLoading tangential_of(const CaseRecord& r) {
  const Kinematics& k = r.kinematics;
  model::TangentialLoading t;
  constexpr model::TangentialKind kinds[] = {
      model::TangentialKind::None, model::TangentialKind::Shift,
      model::TangentialKind::TransientRolling, model::TangentialKind::SteadyRolling};
  t.kind = kinds[r.digits.t];
  t.prescribed = r.digits.f == 1   ? model::TangentialPrescribed::LongitudinalForceLateralCreepage
                 : r.digits.f == 2 ? model::TangentialPrescribed::Forces
                                   : model::TangentialPrescribed::Creepages;
  t.creepage = {k.cksi, k.ceta, k.cphi};
  t.force_x_over_mu_fn = k.fx_rel;
  t.force_y_over_mu_fn = k.fy_rel;
  t.spin_centre_x_mm = k.spinxo;
  t.spin_centre_y_mm = k.spinyo;
  // Only the E=9 digit itself applies the per-element values (E=1 "keep" does not).
  if (r.digits.e == 9) t.extra_slip = k.extra_slip;
  if (r.digits.e == 2) t.spin_terms = model::SpinInRigidSlip::LongitudinalOnly;
  if (r.digits.e == 3) t.spin_terms = model::SpinInRigidSlip::LateralOnly;
  return t;
}

model::SolverOptions solver_of(const CaseRecord& r) {
  const SolverSettings& s = r.solver;
  model::SolverOptions o;
  o.tolerance = s.eps;
  o.max_inner_iterations = s.maxgs;
  o.max_newton_iterations = s.maxnr;
  o.max_normal_tangential_passes = s.maxout;
  // G=0, 3, 4, 5 (SteadyGS, GDsteady: algorithm choices) are served by the default solver.
  o.tangential_method =
      r.digits.g == 2 ? model::TangentialMethod::ConvexGS : model::TangentialMethod::Default;
  if (r.digits.g == 2 || r.digits.g == 3) {
    o.relaxation_adhesion = s.omega_h;
    o.relaxation_slip = s.omega_s;
  }
  o.initial_slip_velocity = s.inislp == 0  ? model::InitialSlipVelocity::Previous
                            : s.inislp > 0 ? model::InitialSlipVelocity::Zero
                                           : model::InitialSlipVelocity::RollingVelocity;
  o.slip_velocity_relaxation = s.omgslp;
  o.max_slip_velocity_passes = std::max(1, s.maxin - 10);
  return o;
}

}  // namespace

model::Friction to_model_friction(int law, const FrictionValues& f, double memdst, double mem_s0) {
  model::Friction m;
  m.static_coefficient = f.fstat;
  m.kinetic_coefficient = f.fkin;
  if (law == 2 || law == 3 || law == 4) {
    m.law = law == 2   ? model::FrictionLawKind::LinearFalling
            : law == 3 ? model::FrictionLawKind::RationalFalling
                       : model::FrictionLawKind::ExponentialFalling;
    // CONTACT clamps the slip velocities of the falling terms to at least 1e-4 mm/s.
    m.terms = {model::FallingTerm{f.params[0], std::max(1e-4, f.params[1])},
               model::FallingTerm{f.params[2], std::max(1e-4, f.params[3])}};
    m.memory_distance_mm = memdst;
    m.memory_floor_speed_mm_s = mem_s0;
  }
  if (law == 6) {  // FREF (in fkin and fstat), TREF DFHEAT DTHEAT
    m.law = model::FrictionLawKind::TemperatureDependent;
    m.temperature = {f.params[0], f.params[1], f.params[2]};
    m.memory_distance_mm = memdst;
    m.memory_floor_speed_mm_s = mem_s0;
  }
  return m;
}

void check_supported(const CaseRecord& record) {
  const ControlDigits& d = record.digits;
  if (d.m != 0 && d.m != 1 && d.m != 2 && d.m != 3 && d.m != 4 && d.m != 5)
    not_supported(fmt::format("material model M={}", d.m));
  if (d.m == 1 && d.t != 3)
    not_supported(fmt::format("viscoelastic bodies M=1 with T={} (steady rolling T=3 only)", d.t));
  if (const auto& mp = record.materials.model_params;
      d.m == 4 && d.t == 2 && mp[2] > 0.0 && mp[3] != 0.0)
    not_supported(fmt::format("a hardening or softening layer (M=4, K_TAU = {}) in rolling T={}",
                              mp[3], d.t));
  if (d.m == 5 && d.t == 1) not_supported("FaStrip M=5 with shifts T=1");
  if (d.m == 5 && d.t == 2) not_supported("FaStrip M=5 with transient rolling T=2");
  // The coefficients in effect (C=0, 1 keep the previous case's).
  const int c = record.materials.influence_type;
  if (c == 4 && d.m == 1)
    not_supported("the inclination correction C=4 with viscoelastic bodies M=1");
  if (c == 4 && record.materials.conformal.if_meth == 1)
    not_supported(
        "the inclination correction C=4 with varying curvature (IF_METH=1); IF_METH=0 fits the "
        "table with a constant curvature");
  // Bilinear elements (C=3): the viscous parts of M=1 and the subsurface stresses integrate
  // piecewise-constant tractions, which would not match the bilinear surface solution.
  if (c == 3 && d.m == 1)
    not_supported("bilinear influence coefficients C=3 with viscoelastic bodies M=1");
  if (c == 3 && d.s >= 1)
    not_supported("subsurface stresses (S>=1) with bilinear influence coefficients C=3");
  if (c == 9 && d.m == 1)
    not_supported("influence coefficients from a file (C=9) with viscoelastic bodies M=1");
  if (d.h != 0 && d.t != 0 && d.t != 3)
    not_supported(fmt::format("temperature H={} with T={} (steady rolling only)", d.h, d.t));
  // FaStrip (M=5) takes the spin into its strips itself, not through the rigid slip.
  if ((d.e == 2 || d.e == 3) && d.m == 5)
    not_supported(
        fmt::format("the spin term dropped from the rigid slip (E={}) with FaStrip M=5", d.e));
  // V=3: one Coulomb coefficient per grid row, for the exact theory with creepages prescribed.
  if (d.v != 0 && d.v != 3) not_supported(fmt::format("variable friction V={}", d.v));
  if (d.v == 3 && (record.friction.law != 0 || d.f != 0 || d.m == 2 || d.m == 3 || d.m == 5))
    not_supported(fmt::format(
        "variable friction V=3 with L={}, F={}, M={} (Coulomb friction, prescribed creepages and "
        "the exact theory only)",
        record.friction.law, d.f, d.m));
  if ((d.t == 1 || d.t == 2) && record.friction.law == 6)
    not_supported(fmt::format("friction law L={} with T={}", record.friction.law, d.t));
  // Fastsim takes falling friction at each element's rigid slip velocity as CONTACT does
  // (simplified/fastsim.hpp): steady rolling (T=3) gives CONTACT's tractcurv cases 91-120
  // (docs/decisions.md), transient rolling and shifts carry each particle's memory along and
  // end in that steady state. FaStrip's strip correction with such a law is not compared with
  // CONTACT yet.
  if (record.friction.law != 0 && d.t >= 1 && d.m == 5)
    not_supported(
        fmt::format("friction law L={} with FaStrip M=5 (not yet validated)", record.friction.law));
}

model::PatchProblem to_patch_problem(const CaseRecord& record) {
  check_supported(record);
  const ControlDigits& d = record.digits;
  model::PatchProblem p;
  p.potential = record.potential;
  p.gap = record.geometry;
  p.bodies = bodies_of(record);
  if (d.b == 1) p.bodies.normal_layer_flexibility_mm3_N = record.materials.flxz;
  if (record.materials.influence_type == 9) {
    const GridExtent ext = grid_extent(record.potential);
    std::optional<ElementSize> element;
    if (ext.known && ext.dx > 0.0 && ext.dy > 0.0) element = ElementSize{ext.dx, ext.dy};
    p.bodies.influence_table = read_influence_file(record.materials.influence_file, element);
  }
  if (record.materials.influence_type == 3)
    p.bodies.traction_elements = model::TractionElements::bilinear;
  if (record.materials.influence_type == 4) {
    // Module 3 gives the inclination table; module 1 has none on the .inp line and takes each
    // conformal patch's row inclinations (wheelrail/patch_setup).
    const Materials::Conformal& cf = record.materials.conformal;
    p.bodies.inclination.variant = cf.variant;
    p.bodies.inclination.varying_curvature = cf.if_meth == 1;
    p.bodies.inclination.y_mm = cf.y;
    p.bodies.inclination.alpha_rad = cf.alpha;
  }
  const Friction& f = record.friction;
  p.friction = to_model_friction(f.law, {f.fstat, f.fkin, f.params}, f.memdst, f.mem_s0);
  if (d.v == 3)
    for (const FrictionValues& row : f.rows) p.friction.row_coefficients.push_back(row.fstat);
  p.normal = normal_of(record);
  p.tangential = tangential_of(record);
  p.rolling = {record.kinematics.chi, record.kinematics.dq, record.kinematics.veloc,
               record.kinematics.facphi};
  p.solver = solver_of(record);
  p.sequence.continue_previous = d.p != 2;
  p.sequence.becomes_previous = d.p != 3;
  p.sequence.force_iteration_from_previous = !(d.i == 0 || d.i == 2);
  // I = 1, 2, 3 all start from the previous case's normal part (inp-format.md §3, I); the
  // pressures are the start of NormCG, not its answer, so a case whose normal problem did not
  // change converges in its first iteration instead of solving again from the coarse grid.
  p.sequence.normal_from_previous = d.i != 0;
  if (d.h >= 1) p.heat = heat_of(record);
  if (d.s >= 1) p.subsurface = record.subsurface.blocks;
  return p;
}

}  // namespace rollcontact::format
