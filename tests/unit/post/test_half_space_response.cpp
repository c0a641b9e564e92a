// Closed-form rectangle solutions against independent half-space results: finite differences of
// the displacements, Love's corner formula, Boussinesq and Cerruti point loads far away, surface
// equilibrium and the surface influence coefficients of src/elastic.

#include <gtest/gtest.h>

#include <cmath>

#include "elastic/influence.hpp"
#include "post/half_space_response.hpp"

namespace rollcontact::post {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Square {
  double x0 = -0.5, x1 = 0.5, y0 = -0.5, y1 = 0.5;
};

HalfSpaceResponse at(double x, double y, double z, const Traction& t, double g = 1.0,
                     double nu = 0.28, Square s = {}) {
  return rectangle_response(x, y, z, s.x0, s.x1, s.y0, s.y1, t, g, nu);
}

TEST(HalfSpaceResponse, GradientMatchesFiniteDifferencesOfDisplacements) {
  const Traction t{0.7, -0.4, 1.3};
  const double g = 1.7, nu = 0.28, h = 1e-5;
  const double points[][3] = {
      {0.1, 0.2, 0.3}, {-0.8, 0.3, 0.05}, {1.7, -2.1, 0.9}, {0.0, 0.0, 2.5}, {0.45, -0.55, 0.2}};
  for (const auto& p : points) {
    const HalfSpaceResponse r = at(p[0], p[1], p[2], t, g, nu);
    for (std::size_t j = 0; j < 3; ++j) {
      double q[3] = {p[0], p[1], p[2]};
      q[j] += h;
      const HalfSpaceResponse up = at(q[0], q[1], q[2], t, g, nu);
      q[j] -= 2 * h;
      const HalfSpaceResponse dn = at(q[0], q[1], q[2], t, g, nu);
      for (std::size_t i = 0; i < 3; ++i) {
        const double fd = (up.u[i] - dn.u[i]) / (2 * h);
        EXPECT_NEAR(r.grad[i][j], fd, 1e-6 * (1.0 + std::abs(fd)))
            << "du" << i << "/dx" << j << " at " << p[0] << "," << p[1] << "," << p[2];
      }
    }
  }
}

// Love (1929) / Holl: σ_zz below a corner of a uniformly loaded L × B rectangle,
// σ_zz = −(p/2π)[atan(LB/(zR₃)) + LBz/R₃ (1/R₁² + 1/R₂²)], R₁² = L²+z², R₂² = B²+z²,
// R₃² = L²+B²+z². Below the centre of a 1×1 square: four 0.5×0.5 corners.
TEST(HalfSpaceResponse, NormalStressBelowCentreMatchesLove) {
  for (double z : {0.1, 0.4, 1.0, 2.5}) {
    const double l = 0.5, b = 0.5;
    const double r1 = l * l + z * z, r2 = b * b + z * z, r3 = std::sqrt(l * l + b * b + z * z);
    const double corner =
        (std::atan(l * b / (z * r3)) + l * b * z / r3 * (1.0 / r1 + 1.0 / r2)) / (2 * kPi);
    const HalfSpaceResponse r = at(0.0, 0.0, z, {0.0, 0.0, 1.0});
    EXPECT_NEAR(r.stress[2][2], -4.0 * corner, 1e-12) << "z = " << z;
  }
}

TEST(HalfSpaceResponse, FarFieldMatchesBoussinesqPointLoad) {
  const double d = 0.01, p = 3.0, force = p * d * d, g = 2.0, nu = 0.3;
  const Square s{-d / 2, d / 2, -d / 2, d / 2};
  const double x = 0.6, y = -0.3, z = 0.8;
  const HalfSpaceResponse r = at(x, y, z, {0.0, 0.0, p}, g, nu, s);
  const double rr = std::hypot(x, y), rho = std::sqrt(rr * rr + z * z);
  // Johnson, Contact Mechanics eqs. 3.19–3.20 (z into the body, compressive load P).
  const double uz = force / (4 * kPi * g) * (2 * (1 - nu) / rho + z * z / (rho * rho * rho));
  const double ur =
      force / (4 * kPi * g) * (rr * z / (rho * rho * rho) - (1 - 2 * nu) * rr / (rho * (rho + z)));
  const double szz = -3 * force * z * z * z / (2 * kPi * std::pow(rho, 5));
  const double srz = -3 * force * rr * z * z / (2 * kPi * std::pow(rho, 5));
  const double tol = 1e-3;
  EXPECT_NEAR(r.u[2], uz, tol * std::abs(uz));
  EXPECT_NEAR(r.u[0] * x / rr + r.u[1] * y / rr, ur, tol * std::abs(ur));
  EXPECT_NEAR(r.stress[2][2], szz, tol * std::abs(szz));
  EXPECT_NEAR(r.stress[0][2] * x / rr + r.stress[1][2] * y / rr, srz, tol * std::abs(srz));
}

TEST(HalfSpaceResponse, FarFieldMatchesCerrutiPointLoad) {
  const double d = 0.01, q = 2.0, force = q * d * d, g = 1.5, nu = 0.25;
  const Square s{-d / 2, d / 2, -d / 2, d / 2};
  const double x = 0.5, y = 0.4, z = 0.7;
  const HalfSpaceResponse r = at(x, y, z, {q, 0.0, 0.0}, g, nu, s);
  const double rho = std::sqrt(x * x + y * y + z * z), rho3 = rho * rho * rho, rz = rho + z;
  const double c = force / (4 * kPi * g);
  // Cerruti (Johnson eq. 3.?; Love 1927 §166): tangential point force Q_x on the surface.
  const double ux =
      c * (1 / rho + x * x / rho3 + (1 - 2 * nu) * (1 / rz - x * x / (rho * rz * rz)));
  const double uy = c * (x * y / rho3 - (1 - 2 * nu) * x * y / (rho * rz * rz));
  const double uz = c * (x * z / rho3 + (1 - 2 * nu) * x / (rho * rz));
  const double szz = -3 * force * x * z * z / (2 * kPi * std::pow(rho, 5));
  const double sxz = -3 * force * x * x * z / (2 * kPi * std::pow(rho, 5));
  const double syz = -3 * force * x * y * z / (2 * kPi * std::pow(rho, 5));
  const double tol = 1e-3;
  EXPECT_NEAR(r.u[0], ux, tol * std::abs(ux));
  EXPECT_NEAR(r.u[1], uy, tol * std::abs(uy));
  EXPECT_NEAR(r.u[2], uz, tol * std::abs(uz));
  EXPECT_NEAR(r.stress[2][2], szz, tol * std::abs(szz));
  EXPECT_NEAR(r.stress[0][2], sxz, tol * std::abs(sxz));
  EXPECT_NEAR(r.stress[1][2], syz, tol * std::abs(syz));
}

TEST(HalfSpaceResponse, SurfaceTractionsAreInEquilibriumWithTheLoad) {
  const Traction t{0.3, -0.2, 1.1};
  for (double z : {0.0, 1e-7}) {
    const HalfSpaceResponse in = at(0.12, -0.2, z, t);
    EXPECT_NEAR(in.stress[2][2], -t.pn, 1e-6);
    EXPECT_NEAR(in.stress[0][2], -t.px, 1e-6);
    EXPECT_NEAR(in.stress[1][2], -t.py, 1e-6);
    const HalfSpaceResponse out = at(1.3, 0.7, z, t);
    EXPECT_NEAR(out.stress[2][2], 0.0, 1e-6);
    EXPECT_NEAR(out.stress[0][2], 0.0, 1e-6);
    EXPECT_NEAR(out.stress[1][2], 0.0, 1e-6);
  }
}

TEST(HalfSpaceResponse, SurfaceDisplacementsMatchInfluenceCoefficients) {
  using elastic::Component;
  using elastic::influence_coefficient;
  const double g1 = 1.3, nu = 0.3, dx = 0.4, dy = 0.7;
  const Square s{-dx / 2, dx / 2, -dy / 2, dy / 2};
  // Two identical bodies: the combined G is g1 and each body takes half of u = C p / G.
  // Body 2 rigid: G = 2 g1, K = (1 − 2ν)/2 and u = u⁽¹⁾ (coupling C_xn, C_yn).
  const double k_rigid = (1 - 2 * nu) / 2;
  for (auto [ox, oy] : {std::pair{0.0, 0.0}, std::pair{0.9, -0.3}, std::pair{-1.4, 2.0}}) {
    const HalfSpaceResponse n = at(ox, oy, 0.0, {0.0, 0.0, 1.0}, g1, nu, s);
    const HalfSpaceResponse tx = at(ox, oy, 0.0, {1.0, 0.0, 0.0}, g1, nu, s);
    const HalfSpaceResponse ty = at(ox, oy, 0.0, {0.0, 1.0, 0.0}, g1, nu, s);
    auto c = [&](Component comp) { return influence_coefficient(comp, ox, oy, dx, dy, nu, 0.0); };
    EXPECT_NEAR(n.u[2], 0.5 * c(Component::nn) / g1, 1e-9);
    EXPECT_NEAR(tx.u[0], 0.5 * c(Component::xx) / g1, 1e-9);
    EXPECT_NEAR(ty.u[1], 0.5 * c(Component::yy) / g1, 1e-9);
    EXPECT_NEAR(tx.u[1], 0.5 * c(Component::xy) / g1, 1e-9);
    const double cxn = influence_coefficient(Component::xn, ox, oy, dx, dy, nu, k_rigid);
    const double cyn = influence_coefficient(Component::yn, ox, oy, dx, dy, nu, k_rigid);
    EXPECT_NEAR(n.u[0], cxn / (2 * g1), 1e-9);
    EXPECT_NEAR(n.u[1], cyn / (2 * g1), 1e-9);
    EXPECT_NEAR(tx.u[2], -cxn / (2 * g1), 1e-9);  // C_nx = −C_xn
  }
}

}  // namespace
}  // namespace rollcontact::post
