// The one admissibility check of a PatchProblem (model::validate), which every front end and
// PatchSolver::solve run: each kind of inadmissible value is named by its field.

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "rollcontact/model/validation.hpp"

namespace rollcontact::model {
namespace {

PatchProblem valid_problem() {
  PatchProblem p;
  p.normal.kind = NormalLoadKind::Force;
  p.normal.force_N = 1000.0;
  p.potential.ipotcn = 1;
  p.potential.mx = p.potential.my = 10;
  p.potential.values = {-1.0, -1.0, 0.2, 0.2};
  p.gap.coeffs = {0.002, 0.0, 0.004, 0.0, 0.0, 0.0};
  return p;
}

/// The field named by the InvalidValueError that validate() throws ("" if it accepts).
std::string rejected_field(const PatchProblem& p) {
  try {
    validate(p);
  } catch (const InvalidValueError& e) {
    EXPECT_EQ(e.code(), ErrorCode::Input);
    return e.field();
  }
  return "";
}

constexpr double kInf = std::numeric_limits<double>::infinity();
const double kNan = std::nan("");

TEST(ModelValidation, AValidProblemPasses) {
  EXPECT_EQ(rejected_field(valid_problem()), "");
}

TEST(ModelValidation, EveryNonFiniteOrOutOfRangeValueIsNamed) {
  struct Case {
    std::function<void(PatchProblem&)> spoil;
    std::string field;
  };
  const std::vector<Case> cases = {
      {[](PatchProblem& p) { p.normal.force_N = kInf; }, "normal.force_N"},
      {[](PatchProblem& p) { p.normal.force_N = -1.0; }, "normal.force_N"},
      {[](PatchProblem& p) {
         p.normal.kind = NormalLoadKind::Approach;
         p.normal.approach_mm = kNan;
       },
       "normal.approach_mm"},
      {[](PatchProblem& p) { p.bodies.body1.shear_modulus_N_mm2 = kInf; },
       "bodies.body1.shear_modulus_N_mm2"},
      {[](PatchProblem& p) { p.bodies.body2.shear_modulus_N_mm2 = 0.0; },
       "bodies.body2.shear_modulus_N_mm2"},
      {[](PatchProblem& p) { p.bodies.body2.poisson_ratio = 0.6; }, "bodies.body2.poisson_ratio"},
      {[](PatchProblem& p) { p.friction.static_coefficient = kNan; },
       "friction.static_coefficient"},
      {[](PatchProblem& p) { p.friction.kinetic_coefficient = -0.1; },
       "friction.kinetic_coefficient"},
      {[](PatchProblem& p) { p.potential.values[2] = 1e30; }, "potential.values[2] (DX)"},
      {[](PatchProblem& p) { p.potential.values[3] = 1e-12; }, "potential.values[3] (DY)"},
      {[](PatchProblem& p) { p.potential.values[0] = kNan; }, "potential.values[0]"},
      {[](PatchProblem& p) { p.potential.mx = 0; }, "potential.mx, my"},
      {[](PatchProblem& p) { p.gap.coeffs[2] = kInf; }, "gap.coeffs[2]"},
      {[](PatchProblem& p) { p.tangential.creepage.lateral = kNan; },
       "tangential.creepage.lateral"},
      {[](PatchProblem& p) {
         p.tangential.extra_slip = {0.0, kInf};
       },
       "tangential.extra_slip[1]"},
      {[](PatchProblem& p) {
         p.tangential.kind = TangentialKind::SteadyRolling;
         p.rolling.step_mm = 0.0;
       },
       "rolling.step_mm"},
      {[](PatchProblem& p) { p.solver.tolerance = kNan; }, "solver.tolerance"},
      {[](PatchProblem& p) {
         SubsurfaceBlock b;
         b.z = {0.0, kInf};
         p.subsurface.push_back(b);
       },
       "subsurface[0].z[1]"},
  };
  for (const Case& c : cases) {
    PatchProblem p = valid_problem();
    c.spoil(p);
    EXPECT_EQ(rejected_field(p), c.field);
  }
}

TEST(ModelValidation, MessageShowsTheValue) {
  PatchProblem p = valid_problem();
  p.normal.force_N = kInf;
  try {
    validate(p);
    FAIL() << "accepted";
  } catch (const InvalidValueError& e) {
    EXPECT_EQ(std::string(e.what()), "normal.force_N = inf: must be finite and positive");
  }
}

TEST(ModelValidation, HeatParametersArePhysical) {
  // The temperature calculation needs conducting bodies (c_p, λ, ρ > 0), a finite bulk
  // temperature, β_pl ∈ [0, 1] and steady rolling or no tangential problem (physics.md §15).
  auto heated = [] {
    PatchProblem p = valid_problem();
    p.tangential.kind = TangentialKind::SteadyRolling;
    p.heat.enabled = true;
    return p;
  };
  EXPECT_EQ(rejected_field(heated()), "");
  PatchProblem p = heated();
  p.heat.body2.conductivity_W_mmC = 0.0;
  EXPECT_EQ(rejected_field(p), "heat.body2.conductivity_W_mmC");
  p = heated();
  p.heat.body1.bulk_temperature_C = kNan;
  EXPECT_EQ(rejected_field(p), "heat.body1.bulk_temperature_C");
  p = heated();
  p.heat.body1.density_kg_mm3 = -7.85e-6;
  EXPECT_EQ(rejected_field(p), "heat.body1.density_kg_mm3");
  p = heated();
  p.heat.plastic_heat_fraction = 1.5;
  EXPECT_EQ(rejected_field(p), "heat.plastic_heat_fraction");
  p = heated();
  p.tangential.kind = TangentialKind::Shift;
  EXPECT_EQ(rejected_field(p), "heat.enabled");
  p.heat.enabled = false;  // without the calculation its parameters are not looked at
  p.heat.body1.heat_capacity_J_kgC = kInf;
  EXPECT_EQ(rejected_field(p), "");
}

TEST(ModelValidation, TemperatureFrictionNeedsHeatAndTheExactTheory) {
  PatchProblem p = valid_problem();
  p.tangential.kind = TangentialKind::SteadyRolling;
  p.friction.law = FrictionLawKind::TemperatureDependent;
  p.friction.temperature = {20.0, -0.1, 300.0};
  EXPECT_EQ(rejected_field(p), "friction.law");  // no temperature calculation
  p.heat.enabled = true;
  EXPECT_EQ(rejected_field(p), "");
  p.friction.temperature.temperature_span_C = 0.0;
  EXPECT_EQ(rejected_field(p), "friction.temperature.temperature_span_C");
  p.friction.temperature.temperature_span_C = 300.0;
  p.bodies.compliance = TangentialCompliance::FastsimThreeFlexibilities;
  EXPECT_EQ(rejected_field(p), "friction.law");
}

TEST(ModelValidation, ViscoelasticBodiesRollAlongPlusXOnly) {
  // The relaxation history runs upstream along +x: a patch rolling backwards (χ = π, a wheel
  // with VS < 0 or a roller rig turning backwards) was solved as if it rolled forwards.
  PatchProblem p = valid_problem();
  p.tangential.kind = TangentialKind::SteadyRolling;
  p.rolling.velocity_mm_per_s = 2000.0;
  p.bodies.viscoelastic = true;
  p.bodies.viscous1 = p.bodies.viscous2 = {0.5, 1e-3};
  EXPECT_EQ(rejected_field(p), "");
  p.rolling.direction_rad = 2.0 * std::numbers::pi;  // the same direction
  EXPECT_EQ(rejected_field(p), "");
  p.rolling.direction_rad = std::numbers::pi;
  EXPECT_EQ(rejected_field(p), "rolling.direction_rad");
  p.bodies.viscoelastic = false;  // elastic bodies roll either way
  EXPECT_EQ(rejected_field(p), "");
}

}  // namespace
}  // namespace rollcontact::model
