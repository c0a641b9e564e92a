// Complete elliptic integrals K, E and Bulirsch's associates B, D.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/hertz.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {
namespace {

constexpr double pi = std::numbers::pi;

TEST(EllipticIntegrals, CircleValues) {
  // k = 0: all integrands are constant in k, B = D = π/4, K = E = π/2.
  const EllipticIntegrals e = complete_elliptic_integrals(0.0);
  EXPECT_NEAR(e.b_assoc, pi / 4, 1e-15);
  EXPECT_NEAR(e.d_assoc, pi / 4, 1e-15);
  EXPECT_NEAR(e.k_first, pi / 2, 1e-15);
  EXPECT_NEAR(e.e_second, pi / 2, 1e-15);
}

TEST(EllipticIntegrals, LemniscaticCase) {
  // k = 1/√2: K = Γ(1/4)²/(4√π), E = K/2 + π/(4K) (closed forms; 17-digit literals).
  const double k = std::sqrt(0.5);
  const EllipticIntegrals e = complete_elliptic_integrals(k);
  const double kk = std::pow(std::tgamma(0.25), 2) / (4.0 * std::sqrt(pi));
  EXPECT_NEAR(e.k_first, 1.8540746773013719, 4e-15);
  EXPECT_NEAR(e.k_first, kk, 4e-15);
  EXPECT_NEAR(e.e_second, 0.5 * kk + pi / (4.0 * kk), 4e-15);
}

TEST(EllipticIntegrals, HighPrecisionReferenceTable) {
  // K, E, B, D from mpmath 1.3 at 40 digits (D = (K − E)/k², B = K − D), k the double nearest
  // to the literal. Our values agree to ~1 ulp; 2e-15 relative allows a few roundings.
  struct Row {
    double k, kk, ee, bb, dd;
  };
  const Row rows[] = {
      {0.01, 1.570835598912152236, 1.5707570561503852873, 0.78540798124266534275,
       0.78542761766948689328},
      {0.1, 1.5747455615173559531, 1.5668619420216682908, 0.78638361194858980792,
       0.78836194956876614519},
      {0.5, 1.6857503548125960429, 1.4674622093394271555, 0.81259777291992049323,
       0.87315258189267554965},
      {0.9, 2.2805491384227703005, 1.1716970527816141138, 0.91159594627319482895,
       1.3689531921495754715},
      {0.99, 3.3566005233611919425, 1.0284758090288040219, 0.98120544700940338786,
       2.3753950763517885546},
      {0.9999, 5.6451482168297478295, 1.0005145000837811284, 0.99958543398283967756,
       4.6455627828469081519},
  };
  for (const Row& r : rows) {
    const EllipticIntegrals e = complete_elliptic_integrals(r.k);
    EXPECT_NEAR(e.k_first / r.kk, 1.0, 2e-15) << "k=" << r.k;
    EXPECT_NEAR(e.e_second / r.ee, 1.0, 2e-15) << "k=" << r.k;
    EXPECT_NEAR(e.b_assoc / r.bb, 1.0, 2e-15) << "k=" << r.k;
    EXPECT_NEAR(e.d_assoc / r.dd, 1.0, 2e-15) << "k=" << r.k;
  }
}

TEST(EllipticIntegrals, AgreeWithStandardLibrary) {
  // libstdc++'s comp_ellint_1/2 (Carlson forms, an independent algorithm) is itself only
  // accurate to ~1e-13 relative for k ≥ 0.9 (checked against mpmath), so this cross-check uses
  // 1e-12; the table above holds the tight assertions.
  for (double k : {0.01, 0.1, 0.3, 0.5, 0.7, 0.9, 0.99, 0.9999}) {
    const EllipticIntegrals e = complete_elliptic_integrals(k);
    EXPECT_NEAR(e.k_first / std::comp_ellint_1(k), 1.0, 1e-12) << "k=" << k;
    EXPECT_NEAR(e.e_second / std::comp_ellint_2(k), 1.0, 1e-12) << "k=" << k;
  }
}

TEST(EllipticIntegrals, HighPrecisionReferenceNearUnitModulus) {
  // k = 0.999999 (the double nearest to it), values from mpmath 1.3 at 40 digits:
  // K = 7.94747977354796703..., E = 1.00000744747772439..., B = 0.999993552512229407...,
  // D = 6.94748622103573762... Tolerance 4 ulp-ish relative.
  const EllipticIntegrals e = complete_elliptic_integrals(0.999999);
  EXPECT_NEAR(e.k_first / 7.947479773547967033, 1.0, 1e-15);
  EXPECT_NEAR(e.e_second / 1.000007447477724392, 1.0, 1e-15);
  EXPECT_NEAR(e.b_assoc / 0.9999935525122294073, 1.0, 1e-15);
  EXPECT_NEAR(e.d_assoc / 6.947486221035737625, 1.0, 1e-15);
}

TEST(EllipticIntegrals, NearUnitModulusAsymptotics) {
  // For m_c = k_c² → 0: K = L + (m_c/4)(L − 1) + O(m_c² L), E = 1 + (m_c/2)(L − ½) + O(m_c² L)
  // with L = ln(4/k_c). At m_c ≤ 1e-12 the neglected terms are < 1e-22, far below 1e-15.
  for (double mc : {1e-12, 1e-20, 1e-40, 1e-100}) {
    const double kc = std::sqrt(mc);
    const double big_l = std::log(4.0 / kc);
    const EllipticIntegrals e = complete_elliptic_integrals_mc(mc);
    EXPECT_NEAR(e.k_first / (big_l + 0.25 * mc * (big_l - 1.0)), 1.0, 4e-15) << "mc=" << mc;
    EXPECT_NEAR(e.e_second, 1.0 + 0.5 * mc * (big_l - 0.5), 4e-15) << "mc=" << mc;
    // B → 1 and D → L − 1 without cancellation.
    EXPECT_NEAR(e.b_assoc, 1.0, 1e-11) << "mc=" << mc;
    EXPECT_NEAR(e.d_assoc / (big_l - 1.0), 1.0, 1e-10) << "mc=" << mc;
  }
}

TEST(EllipticIntegrals, LegendreRelation) {
  // E K' + E' K − K K' = π/2 with primed integrals at the complementary parameter. It mixes
  // both ends of the range, so it checks the k → 1 branch against the k → 0 branch.
  for (double mc : {1e-14, 1e-8, 0.01, 0.25, 0.5, 0.9}) {
    const EllipticIntegrals e = complete_elliptic_integrals_mc(mc);
    const EllipticIntegrals ep = complete_elliptic_integrals_mc(1.0 - mc);
    const double lhs = e.e_second * ep.k_first + ep.e_second * e.k_first - e.k_first * ep.k_first;
    EXPECT_NEAR(lhs, pi / 2, 2e-14) << "mc=" << mc;
  }
}

TEST(EllipticIntegrals, ModulusAndParameterFormsAgree) {
  for (double k : {0.2, 0.8, 0.999}) {
    const EllipticIntegrals a = complete_elliptic_integrals(k);
    const EllipticIntegrals b = complete_elliptic_integrals_mc(1.0 - k * k);
    EXPECT_NEAR(a.k_first, b.k_first, 1e-14 * a.k_first);
    EXPECT_NEAR(a.e_second, b.e_second, 1e-14 * a.e_second);
  }
}

TEST(EllipticIntegrals, RejectsOutOfDomain) {
  EXPECT_THROW(complete_elliptic_integrals(1.0), ProblemError);
  EXPECT_THROW(complete_elliptic_integrals(std::nan("")), ProblemError);
  EXPECT_THROW(complete_elliptic_integrals_mc(0.0), ProblemError);
  EXPECT_THROW(complete_elliptic_integrals_mc(1.5), ProblemError);
}

}  // namespace
}  // namespace rollcontact::geometry
