// The pressure error of a penalty compliance L = C_d/(αK): pmax with the compressible layer
// (B=1) rises monotonically with α to the exact value, and a very compliant layer is a Winkler
// foundation whose pmax and area for a paraboloid gap are known in closed form.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "rollcontact/errors.hpp"
#include "rollcontact/fe_advice.hpp"

namespace rollcontact::fe_advice {
namespace {

TEST(FeLayerPressure, PmaxRisesWithPenaltyFactorToTheExactValue) {
  NormalContactCase c;   // the paper's 100 kN case
  c.grid_step_mm = 0.5;  // coarser than the CLI's 0.25 mm: the trend, not the digits
  const FeContactSettings fe;
  std::vector<double> compliances{0.0};
  for (const double alpha : penalty_factor_sweep())
    compliances.push_back(stability_advice(fe, alpha).layer_compliance_mm3_N);
  const std::vector<NormalContactResult> r = solve_normal_contacts(c, compliances);
  ASSERT_EQ(r.size(), compliances.size());
  const NormalContactResult& exact = r.front();
  EXPECT_NEAR(exact.area_mm2, 191.0, 191.0 * 0.03);  // the Hertzian 190.8 mm² on this grid
  EXPECT_NEAR(exact.pmax_N_mm2, 786.0, 786.0 * 0.02);
  for (std::size_t i = 2; i < r.size(); ++i) {
    EXPECT_GT(r[i].pmax_N_mm2, r[i - 1].pmax_N_mm2) << i;
    EXPECT_LE(r[i].area_mm2, r[i - 1].area_mm2) << i;
    EXPECT_LT(r[i].pmax_N_mm2, exact.pmax_N_mm2 * (1.0 + 1e-9)) << i;
  }
  EXPECT_NEAR(r.back().pmax_N_mm2 / exact.pmax_N_mm2, 1.0, 0.005);  // α = 409.6
  EXPECT_LT(r[1].pmax_N_mm2 / exact.pmax_N_mm2, 0.8);               // α = 0.05: far off
}

TEST(FeLayerPressure, ACompliantLayerIsAWinklerFoundation) {
  // L·E*/a ≫ 1: the bodies' own deformation is a small correction to p = (δ − h)/L.
  NormalContactCase c;
  c.normal_force_N = 1000.0;
  c.curvature_x_1_mm = 0.01;
  c.curvature_y_1_mm = 0.004;
  const double l = 0.05;  // mm³/N
  const NormalContactResult w = winkler_paraboloid(c, l);
  c.grid_step_mm = std::sqrt(w.approach_mm / c.curvature_x_1_mm) / 30.0;
  const NormalContactResult solved = solve_normal_contacts(c, std::vector<double>{l}).front();
  EXPECT_NEAR(solved.pmax_N_mm2 / w.pmax_N_mm2, 1.0, 0.01);
  EXPECT_NEAR(solved.area_mm2 / w.area_mm2, 1.0, 0.02);
  EXPECT_GT(solved.approach_mm, w.approach_mm);  // plus the bodies' deformation
}

TEST(FeLayerPressure, WinklerLimitInClosedForm) {
  NormalContactCase c;
  c.normal_force_N = 2.0;
  c.curvature_x_1_mm = 1.0;
  c.curvature_y_1_mm = 1.0;
  // F = πδ²/(2L√(AB)): L = 1, A = B = 1, F = 2 → δ = √(4/π), pmax = δ, area = πδ.
  const NormalContactResult w = winkler_paraboloid(c, 1.0);
  const double delta = std::sqrt(4.0 / std::acos(-1.0));
  EXPECT_NEAR(w.approach_mm, delta, 1e-14);
  EXPECT_NEAR(w.pmax_N_mm2, delta, 1e-14);
  EXPECT_NEAR(w.area_mm2, std::acos(-1.0) * delta, 1e-13);
}

TEST(FeLayerPressure, RefusesBadCases) {
  NormalContactCase c;
  c.curvature_y_1_mm = 0.0;
  EXPECT_THROW((void)solve_normal_contacts(c, std::vector<double>{0.0}), InvalidValueError);
  c = {};
  c.normal_force_N = -1.0;
  EXPECT_THROW((void)winkler_paraboloid(c, 1e-5), InvalidValueError);
  c = {};
  EXPECT_THROW((void)solve_normal_contacts(c, std::vector<double>{-1e-5}), InvalidValueError);
}

}  // namespace
}  // namespace rollcontact::fe_advice
