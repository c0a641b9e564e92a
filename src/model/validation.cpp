#include "rollcontact/model/validation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <string>
#include <string_view>
#include <vector>

namespace rollcontact::model {

namespace {

// The limits of the .inp and TOML readers (spec/inp-format.md), so that all front ends agree.
constexpr double kMinShearModulus = 1e-5;  // [N/mm²]

[[noreturn]] void reject(std::string_view field, double value, std::string_view why) {
  throw InvalidValueError(std::string(field), fmt::format(" = {}: {}", value, why));
}

void finite(std::string_view field, double v) {
  if (!std::isfinite(v)) reject(field, v, "must be a finite number");
}

void finite_all(std::string_view field, const std::vector<double>& values) {
  for (std::size_t i = 0; i < values.size(); ++i)
    if (!std::isfinite(values[i]))
      reject(fmt::format("{}[{}]", field, i), values[i], "must be a finite number");
}

void at_least(std::string_view field, double v, double lo) {
  if (!(std::isfinite(v) && v >= lo))
    reject(field, v, fmt::format("must be a finite number of at least {}", lo));
}

void element_size(std::string_view field, double v) {
  if (!(std::isfinite(v) && v >= kMinElementSize_mm && v <= kMaxElementSize_mm))
    reject(field, v,
           fmt::format("element size must lie in [{}, {}] mm", kMinElementSize_mm,
                       kMaxElementSize_mm));
}

void positive(std::string_view field, double v) {
  if (!(std::isfinite(v) && v > 0.0)) reject(field, v, "must be finite and positive");
}

void body(std::string_view name, const ElasticBody& b) {
  const double nu = b.poisson_ratio;
  if (!(std::isfinite(nu) && nu >= 0.0 && nu <= 0.5))
    reject(fmt::format("bodies.{}.poisson_ratio", name), nu, "must lie in [0, 0.5]");
  at_least(fmt::format("bodies.{}.shear_modulus_N_mm2", name), b.shear_modulus_N_mm2,
           kMinShearModulus);
}

void potential_contact(const PotentialContact& pc) {
  if (pc.mx < 1 || pc.my < 1)
    throw InvalidValueError("potential.mx, my",
                            fmt::format(" = {}, {}: need at least one element", pc.mx, pc.my));
  for (std::size_t i = 0; i < pc.values.size(); ++i)
    finite(fmt::format("potential.values[{}]", i), pc.values[i]);
  // Forms 1 and 3 give the element size itself.
  if (pc.ipotcn == 1 || pc.ipotcn == 3) {
    element_size("potential.values[2] (DX)", pc.values[2]);
    element_size("potential.values[3] (DY)", pc.values[3]);
  }
}

void gap(const UndeformedDistance& g) {
  finite_all("gap.coeffs", g.coeffs);
  finite("gap.xm", g.xm);
  finite("gap.rm", g.rm);
  finite("gap.y1", g.y1);
  finite("gap.dy1", g.dy1);
  finite_all("gap.values", g.values);
  finite_all("gap.planform", g.planform);
  finite_all("gap.patch_factors", g.patch_factors);
}

void loading(const PatchProblem& p) {
  if (p.normal.kind == NormalLoadKind::Force)
    positive("normal.force_N", p.normal.force_N);
  else
    finite("normal.approach_mm", p.normal.approach_mm);
  const TangentialLoading& t = p.tangential;
  finite("tangential.creepage.longitudinal", t.creepage.longitudinal);
  finite("tangential.creepage.lateral", t.creepage.lateral);
  finite("tangential.creepage.spin_rad_per_mm", t.creepage.spin_rad_per_mm);
  finite("tangential.force_x_over_mu_fn", t.force_x_over_mu_fn);
  finite("tangential.force_y_over_mu_fn", t.force_y_over_mu_fn);
  finite("tangential.spin_centre_x_mm", t.spin_centre_x_mm);
  finite("tangential.spin_centre_y_mm", t.spin_centre_y_mm);
  finite_all("tangential.extra_slip", t.extra_slip);
  finite("rolling.direction_rad", p.rolling.direction_rad);
  finite("rolling.spin_offset_factor", p.rolling.spin_offset_factor);
  if (t.kind == TangentialKind::TransientRolling || t.kind == TangentialKind::SteadyRolling) {
    positive("rolling.step_mm", p.rolling.step_mm);
    positive("rolling.velocity_mm_per_s", p.rolling.velocity_mm_per_s);
  }
}

void friction_and_solver(const PatchProblem& p) {
  at_least("friction.static_coefficient", p.friction.static_coefficient, 0.0);
  at_least("friction.kinetic_coefficient", p.friction.kinetic_coefficient, 0.0);
  if (p.friction.velocity_dependent()) {
    for (const FallingTerm& term : p.friction.terms) {
      at_least("friction.terms.coefficient", term.coefficient, 0.0);
      positive("friction.terms.speed_mm_s", term.speed_mm_s);
    }
    at_least("friction.memory_distance_mm", p.friction.memory_distance_mm, 0.0);
    at_least("friction.memory_floor_speed_mm_s", p.friction.memory_floor_speed_mm_s, 0.0);
  }
  if (p.bodies.viscoelastic) {
    at_least("bodies.viscous1.creep_ratio", p.bodies.viscous1.creep_ratio, 0.0);
    at_least("bodies.viscous2.creep_ratio", p.bodies.viscous2.creep_ratio, 0.0);
    at_least("bodies.viscous1.relaxation_time_s", p.bodies.viscous1.relaxation_time_s, 0.0);
    at_least("bodies.viscous2.relaxation_time_s", p.bodies.viscous2.relaxation_time_s, 0.0);
    // The delayed response is integrated along the rolling path (spec-additions §B5).
    if (p.tangential.kind != TangentialKind::SteadyRolling)
      throw InvalidValueError("bodies.viscoelastic",
                              ": viscoelastic bodies need steady rolling (T=3)");
    positive("rolling.velocity_mm_per_s", p.rolling.velocity_mm_per_s);
    // The history runs upstream along +x only: a patch rolling in another direction (a wheel
    // rolling backwards has χ = π) was solved as if it rolled along +x. CONTACT refuses it too.
    if (std::abs(std::remainder(p.rolling.direction_rad, 2.0 * std::numbers::pi)) > 1e-9)
      throw InvalidValueError(
          "rolling.direction_rad",
          fmt::format(" = {:.6g} rad: viscoelastic bodies (M=1) roll along +x only (CHI = 0); a "
                      "wheel rolling backwards is not supported",
                      p.rolling.direction_rad));
  }
  if (p.friction.temperature_dependent()) {
    const TemperatureTerm& t = p.friction.temperature;
    finite("friction.temperature.reference_temperature_C", t.reference_temperature_C);
    finite("friction.temperature.change", t.change);
    positive("friction.temperature.temperature_span_C", t.temperature_span_C);
    at_least("friction.memory_distance_mm", p.friction.memory_distance_mm, 0.0);
    at_least("friction.memory_floor_speed_mm_s", p.friction.memory_floor_speed_mm_s, 0.0);
    // μ(T) needs the surface temperature of the exact steady-rolling solution (§10.3, §15).
    if (!p.heat.enabled)
      throw InvalidValueError("friction.law", ": temperature-dependent friction needs heat");
    if (p.bodies.compliance != TangentialCompliance::ExactHalfSpace)
      throw InvalidValueError("friction.law",
                              ": temperature-dependent friction needs the exact theory");
  }
  const SimplifiedParameters& s = p.bodies.simplified;
  finite("bodies.simplified.flexibility_mm3_N", s.flexibility_mm3_N);
  finite("bodies.simplified.k0", s.k0);
  finite("bodies.simplified.alpha_inf", s.alpha_inf);
  finite("bodies.simplified.beta", s.beta);
  positive("solver.tolerance", p.solver.tolerance);
  finite("solver.relaxation_adhesion", p.solver.relaxation_adhesion);
  finite("solver.relaxation_slip", p.solver.relaxation_slip);
}

void thermal_body(std::string_view name, const ThermalBody& b) {
  finite(fmt::format("heat.{}.bulk_temperature_C", name), b.bulk_temperature_C);
  positive(fmt::format("heat.{}.heat_capacity_J_kgC", name), b.heat_capacity_J_kgC);
  positive(fmt::format("heat.{}.conductivity_W_mmC", name), b.conductivity_W_mmC);
  positive(fmt::format("heat.{}.density_kg_mm3", name), b.density_kg_mm3);
}

// The flash temperature of physics.md §15 is a steady-state result: steady rolling, or no
// tangential problem (T=0: the bulk temperatures are the result).
void heat(const PatchProblem& p) {
  if (!p.heat.enabled) return;
  thermal_body("body1", p.heat.body1);
  thermal_body("body2", p.heat.body2);
  const double beta = p.heat.plastic_heat_fraction;
  if (!(std::isfinite(beta) && beta >= 0.0 && beta <= 1.0))
    reject("heat.plastic_heat_fraction", beta, "must lie in [0, 1]");
  const TangentialKind kind = p.tangential.kind;
  if (kind != TangentialKind::None && kind != TangentialKind::SteadyRolling)
    throw InvalidValueError("heat.enabled",
                            ": the surface temperature needs steady rolling (or no tangential "
                            "problem)");
}

void subsurface(const std::vector<SubsurfaceBlock>& blocks) {
  for (std::size_t b = 0; b < blocks.size(); ++b) {
    const SubsurfaceBlock& s = blocks[b];
    const std::string name = fmt::format("subsurface[{}]", b);
    finite(name + ".zl", s.zl);
    finite(name + ".dz", s.dz);
    finite_all(name + ".x", s.x);
    finite_all(name + ".y", s.y);
    finite_all(name + ".z", s.z);
  }
}

}  // namespace

void validate(const PatchProblem& problem) {
  potential_contact(problem.potential);
  gap(problem.gap);
  body("body1", problem.bodies.body1);
  body("body2", problem.bodies.body2);
  friction_and_solver(problem);
  loading(problem);
  heat(problem);
  subsurface(problem.subsurface);
}

}  // namespace rollcontact::model
