// Surface temperatures of steady rolling (spec/physics.md §15) against the continuous moving-band
// solution (Jaeger, large Péclet number: heat conducts only into the depth, so a surface point
// that has spent the time t = x/V under a uniform flux q₁ has risen by 2q₁√(t/π)/β₁), the
// partition of the heat between the bodies, and the bulk and contact temperatures.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "post/surface_temperature.hpp"

namespace rollcontact::post {
namespace {

constexpr double kPi = std::numbers::pi;

/// Steel of ertz_temperature.inp: c_p 450 J/(kg °C), λ 50e-3 W/(mm °C), ρ 7.85e-6 kg/mm³.
model::ThermalBody steel(double bulk_C) {
  return {bulk_C, 450.0, 50e-3, 7.85e-6};
}

model::SurfaceHeat identical_steel(double t01, double t02) {
  model::SurfaceHeat h;
  h.enabled = true;
  h.body1 = steel(t01);
  h.body2 = steel(t02);
  return h;
}

/// One row of `mx` elements of length dx; elements [first, first + count) in contact with
/// pressure p, sliding with slip speed `speed` [mm/s] against traction μp (heat flux
/// q = μ·p·speed), rolling at V with step δq = dx. χ = π: the leading edge is at low x.
struct Band {
  int mx = 200, first = 20, count = 40;
  double dx = 0.1, p = 500.0, mu = 0.3, speed = 1000.0, veloc = 30000.0, chi = kPi;
  bool slip = true;

  [[nodiscard]] double flux() const { return slip ? mu * p * speed : 0.0; }  // [mW/mm²]

  [[nodiscard]] Solution solution() const {
    Solution s;
    s.grid = Grid{mx, 1, 0.0, -0.5, dx, 1.0};
    const auto n = static_cast<std::size_t>(mx);
    s.pn.assign(n, 0.0);
    s.px.assign(n, 0.0);
    s.py.assign(n, 0.0);
    s.sx.assign(n, 0.0);
    s.sy.assign(n, 0.0);
    s.state.assign(n, ElementState::Exterior);
    s.kinematics = {chi, dx, veloc, dx / veloc};
    for (int k = first; k < first + count; ++k) {
      const auto i = static_cast<std::size_t>(k);
      s.pn[i] = p;
      s.state[i] = slip ? ElementState::Slip : ElementState::Adhesion;
      if (!slip) continue;
      s.px[i] = mu * p;
      s.sx[i] = -speed * s.kinematics.dt / s.kinematics.dq;  // S/δq, opposite to p_t
    }
    return s;
  }

  /// Distance of element k's centre from the leading edge of the band [mm].
  [[nodiscard]] double from_lead(int k) const { return (k - first + 0.5) * dx; }
};

/// The continuous moving-band rise of both surfaces at distance x from the leading edge
/// [°C]: flux q enters the bodies in proportion to their effusivities, so that both rise by
/// 2q/((β₁ + β₂)√(πV))·(√x − √(x − 2a)⁺).
double jaeger_rise(const model::SurfaceHeat& h, const Band& b, double x) {
  const double length = b.count * b.dx;
  const double scale =
      2.0 * b.flux() / ((h.body1.effusivity() + h.body2.effusivity()) * std::sqrt(kPi * b.veloc));
  return scale * (std::sqrt(x) - std::sqrt(std::max(0.0, x - length)));
}

TEST(SurfaceTemperature, EffusivityInReportUnits) {
  // β = 1000·√(λρc_p) = 1000·√(50e-3 · 7.85e-6 · 450) = 13.29 mW·√s/(mm² °C).
  EXPECT_NEAR(steel(0.0).effusivity(), 13.2900, 1e-4);
}

TEST(SurfaceTemperature, FlashKernelIsTheDifferenceOfSquareRoots) {
  EXPECT_DOUBLE_EQ(flash_kernel(0.0, 0.2), 2.0 * std::sqrt(0.1));  // own element, §15
  EXPECT_DOUBLE_EQ(flash_kernel(0.4, 0.2), std::sqrt(0.5) - std::sqrt(0.3));
  EXPECT_DOUBLE_EQ(flash_kernel(-0.2, 0.2), 0.0);  // no heat flows upstream
}

TEST(SurfaceTemperature, BehindTheBandEqualsTheMovingBandSolution) {
  // Behind the band the element sources telescope exactly:
  // Σ_j [√(x_k − x_j + δx/2) − √(x_k − x_j − δx/2)] = √x_k − √(x_k − 2a).
  const Band b;
  const model::SurfaceHeat h = identical_steel(0.0, 0.0);
  const SurfaceTemperatures t = surface_temperatures(h, b.solution(), true);
  for (int k = b.first + b.count; k < b.mx; ++k) {
    const double exact = jaeger_rise(h, b, b.from_lead(k));
    EXPECT_NEAR(t.temp1[static_cast<std::size_t>(k)], exact, 1e-10 * exact) << k;
    EXPECT_NEAR(t.temp2[static_cast<std::size_t>(k)], exact, 1e-10 * exact) << k;
  }
}

TEST(SurfaceTemperature, UnderTheBandTheElementFormulaConvergesToJaeger) {
  // Under the band the sum telescopes to √x_k − √(δx/2), and the own element adds 2√(δx/2):
  // T_k = rise(√x_k + √(δx/2)), the continuous solution plus one half-element term. Against
  // the element average of the continuous solution, (1/δx)∫√x dx, the difference stays below
  // 2√(δx/2)·rise and shrinks like √δx: halving δx divides it by √2.
  const model::SurfaceHeat h = identical_steel(0.0, 0.0);
  double previous_error = 0.0;
  for (int refine = 0; refine < 3; ++refine) {
    Band b;
    b.dx = 0.2 / (1 << refine);
    b.first = 10 << refine;
    b.count = 40 << refine;  // the same band, 8 mm long
    b.mx = 2 * b.first + b.count;
    const SurfaceTemperatures t = surface_temperatures(h, b.solution(), true);
    const double unit = jaeger_rise(h, b, 1.0);  // rise per √mm
    double worst = 0.0;
    for (int k = b.first; k < b.first + b.count; ++k) {
      const double x = b.from_lead(k);
      const double temp = t.temp1[static_cast<std::size_t>(k)];
      EXPECT_NEAR(temp, unit * (std::sqrt(x) + std::sqrt(0.5 * b.dx)), 1e-10 * temp);
      const double lo = x - 0.5 * b.dx, hi = x + 0.5 * b.dx;
      const double average = unit * (2.0 / 3.0) * (hi * std::sqrt(hi) - lo * std::sqrt(lo)) / b.dx;
      worst = std::max(worst, std::abs(temp - average));
    }
    EXPECT_LE(worst, 2.0 * std::sqrt(0.5 * b.dx) * unit);
    if (refine > 0) {
      EXPECT_NEAR(previous_error / worst, std::sqrt(2.0), 0.02) << b.dx;
    }
    previous_error = worst;
    // The maximum is at the trailing element and tends to the band's 2q√(2a)/(...).
    EXPECT_NEAR(t.max1, jaeger_rise(h, b, 8.0), 2.0 * std::sqrt(0.5 * b.dx) * unit);
  }
}

TEST(SurfaceTemperature, WithoutTangentialProblemTheBulkTemperaturesAreTheResult) {
  // T = 0 (no rolling): BKTEMP1 and BKTEMP2 everywhere, whatever the tractions.
  const Band b;
  const SurfaceTemperatures t =
      surface_temperatures(identical_steel(20.0, 150.0), b.solution(), false);
  for (std::size_t i = 0; i < t.temp1.size(); ++i) {
    EXPECT_DOUBLE_EQ(t.temp1[i], 20.0);
    EXPECT_DOUBLE_EQ(t.temp2[i], 150.0);
  }
  EXPECT_DOUBLE_EQ(t.max1, 20.0);
  EXPECT_DOUBLE_EQ(t.max2, 150.0);
}

TEST(SurfaceTemperature, RollingWithoutSlipTakesTheContactTemperature) {
  // ertz_temperature case 2: cold body 1, body 2 at 150 °C, no slip: 75 °C in the contact,
  // the bulk temperatures ahead of it, relaxation behind it.
  Band b;
  b.slip = false;
  const SurfaceTemperatures t =
      surface_temperatures(identical_steel(0.0, 150.0), b.solution(), true);
  for (int k = 0; k < b.first; ++k) {
    EXPECT_DOUBLE_EQ(t.temp1[static_cast<std::size_t>(k)], 0.0);
    EXPECT_DOUBLE_EQ(t.temp2[static_cast<std::size_t>(k)], 150.0);
  }
  for (int k = b.first; k < b.first + b.count; ++k) {
    EXPECT_DOUBLE_EQ(t.temp1[static_cast<std::size_t>(k)], 75.0);
    EXPECT_DOUBLE_EQ(t.temp2[static_cast<std::size_t>(k)], 75.0);
  }
  EXPECT_DOUBLE_EQ(std::max(t.max1, t.max2), 75.0);
}

TEST(SurfaceTemperature, BehindTheContactTheSurfacesRelaxLikeAnInsulatedHalfSpace) {
  // After a contact of duration t_c at a fixed surface temperature step ΔT, an insulated
  // half-space keeps ΔT·(2/π)·asin√(t_c/t): continuous at the trailing edge, decaying
  // monotonically, and like ΔT·(2/π)√(t_c/t) far behind (a heat impulse, T ∝ 1/√t).
  Band b;
  b.slip = false;
  b.mx = 4000;
  const SurfaceTemperatures t =
      surface_temperatures(identical_steel(0.0, 150.0), b.solution(), true);
  const int trail = b.first + b.count - 1;
  const double first_behind = t.temp1[static_cast<std::size_t>(trail + 1)];
  EXPECT_LT(first_behind, 75.0);
  EXPECT_GT(first_behind, 0.9 * 75.0);
  for (int k = trail + 2; k < b.mx; ++k)
    EXPECT_LT(t.temp1[static_cast<std::size_t>(k)], t.temp1[static_cast<std::size_t>(k - 1)]);
  // asin z = z + z³/6 + O(z⁵) with z² = t_c/t ≈ 0.01 here.
  const int far = b.mx - 1;
  const double z2 = b.count * b.dx / b.from_lead(far);
  const double impulse = 75.0 * (2.0 / kPi) * std::sqrt(z2) * (1.0 + z2 / 6.0);
  EXPECT_NEAR(t.temp1[static_cast<std::size_t>(far)], impulse, 1e-4 * impulse);
  // Body 2 cools from 150 °C by the same fraction of its step.
  EXPECT_NEAR(150.0 - t.temp2[static_cast<std::size_t>(far)], impulse, 1e-3 * impulse);
}

TEST(SurfaceTemperature, IdenticalBodiesShareTheHeatEqually) {
  // ε = ½: each surface rises like one half-space that takes half of the flux, 2(q/2)√x/(β√πV).
  const Band b;
  const model::SurfaceHeat h = identical_steel(0.0, 0.0);
  const SurfaceTemperatures t = surface_temperatures(h, b.solution(), true);
  const double beta = h.body1.effusivity();
  const int k = b.first + b.count + 5;  // behind the band: the exact telescoped sum
  const double x = b.from_lead(k), length = b.count * b.dx;
  const double half_flux_rise = 2.0 * (0.5 * b.flux()) / (beta * std::sqrt(kPi * b.veloc)) *
                                (std::sqrt(x) - std::sqrt(x - length));
  EXPECT_NEAR(t.temp1[static_cast<std::size_t>(k)], half_flux_rise, 1e-10 * half_flux_rise);
  EXPECT_DOUBLE_EQ(t.temp1[static_cast<std::size_t>(k)], t.temp2[static_cast<std::size_t>(k)]);
}

TEST(SurfaceTemperature, DissimilarBodiesTakeHeatInProportionToTheirEffusivity) {
  // λ₂ = 16λ₁: β₂ = 4β₁. The contact temperature is the β-weighted mean of the bulk ones; body 1
  // takes the fraction β₁/(β₁ + β₂) = 1/5 of the heat and rises by 2q₁√x/(β₁√πV), body 2 the
  // rest with the same rise, so the two surfaces in contact stay at one temperature.
  const Band b;
  model::SurfaceHeat h = identical_steel(10.0, 60.0);
  h.body2.conductivity_W_mmC *= 16.0;
  const double b1 = h.body1.effusivity(), b2 = h.body2.effusivity();
  ASSERT_NEAR(b2, 4.0 * b1, 1e-12 * b2);
  const SurfaceTemperatures t = surface_temperatures(h, b.solution(), true);
  const double t_contact = (b1 * 10.0 + b2 * 60.0) / (b1 + b2);  // 50 °C
  EXPECT_NEAR(t_contact, 50.0, 1e-12);
  const int k = b.first + b.count - 1;  // trailing contact element
  const double sum = std::sqrt(b.from_lead(k)) + std::sqrt(0.5 * b.dx);
  const double q1 = b.flux() * b1 / (b1 + b2), q2 = b.flux() - q1;
  const double rise1 = 2.0 * q1 / (b1 * std::sqrt(kPi * b.veloc)) * sum;
  const double rise2 = 2.0 * q2 / (b2 * std::sqrt(kPi * b.veloc)) * sum;
  EXPECT_NEAR(t.temp1[static_cast<std::size_t>(k)], t_contact + rise1, 1e-10 * rise1);
  EXPECT_NEAR(t.temp2[static_cast<std::size_t>(k)], t_contact + rise2, 1e-10 * rise2);
}

TEST(SurfaceTemperature, RollingDirectionMirrorsTheField) {
  // χ = 0 rolls towards +x (leading edge at high x): the mirror image of χ = π.
  Band b;
  b.first = 30;
  b.count = 25;
  b.mx = 100;
  Solution back = b.solution();
  b.chi = 0.0;
  Solution forward = b.solution();
  // A non-uniform flux makes the mirror test sensitive to the order of the sweep.
  for (int k = 0; k < b.mx; ++k) {
    const auto i = static_cast<std::size_t>(k);
    back.pn[i] *= 1.0 + 0.01 * k;
    back.px[i] *= 1.0 + 0.01 * k;
  }
  for (int k = 0; k < b.mx; ++k) {
    const auto i = static_cast<std::size_t>(k), m = static_cast<std::size_t>(b.mx - 1 - k);
    forward.pn[m] = back.pn[i];
    forward.px[m] = back.px[i];
    forward.sx[m] = back.sx[i];
    forward.state[m] = back.state[i];
  }
  const model::SurfaceHeat h = identical_steel(0.0, 150.0);
  const SurfaceTemperatures tb = surface_temperatures(h, back, true);
  const SurfaceTemperatures tf = surface_temperatures(h, forward, true);
  for (int k = 0; k < b.mx; ++k) {
    const auto i = static_cast<std::size_t>(k), m = static_cast<std::size_t>(b.mx - 1 - k);
    EXPECT_NEAR(tf.temp1[m], tb.temp1[i], 1e-9) << k;
    EXPECT_NEAR(tf.temp2[m], tb.temp2[i], 1e-9) << k;
  }
  EXPECT_DOUBLE_EQ(tf.max1, tb.max1);
  // Heat is carried downstream: the hottest element is the trailing one.
  const auto hottest = std::max_element(tb.temp1.begin(), tb.temp1.end()) - tb.temp1.begin();
  EXPECT_EQ(hottest, b.first + b.count - 1);
}

TEST(SurfaceTemperature, PlasticFlowHeatsWithItsFraction) {
  // A Plastic element does not slide (S = 0); the layer flows by |Δu_pl| per step, and the
  // fraction β_pl of that work becomes heat: q = β_pl·|Δu_pl|/δt·|p_t|.
  Band b;
  b.count = 1;
  Solution s = b.solution();
  const auto i = static_cast<std::size_t>(b.first);
  s.sx[i] = 0.0;
  s.state[i] = ElementState::Plastic;
  std::vector<double> flow(static_cast<std::size_t>(b.mx), 0.0);
  flow[i] = 0.004;  // [mm] per step
  const double q = frictional_heat_flux(s, 0.25, flow)[i];
  EXPECT_NEAR(q, 0.25 * 0.004 / s.kinematics.dt * b.mu * b.p, 1e-9 * q);
  EXPECT_DOUBLE_EQ(frictional_heat_flux(s, 0.0, flow)[i], 0.0);
  model::SurfaceHeat h = identical_steel(0.0, 0.0);
  h.plastic_heat_fraction = 0.25;
  const SurfaceTemperatures t = surface_temperatures(h, s, true, flow);
  const double own =
      2.0 * q / (2.0 * h.body1.effusivity() * std::sqrt(kPi * b.veloc)) * flash_kernel(0.0, b.dx);
  EXPECT_NEAR(t.temp1[i], own, 1e-10 * own);
}

}  // namespace
}  // namespace rollcontact::post
