// Half-space response from the corner sums of the rectangle potentials (half_space_response.hpp).
//
// Johnson (Contact Mechanics, eq. 3.7; Love 1929) writes the displacements of the half-space
// z ≥ 0 under surface tractions (q_x, q_y, p) acting on it, with F = q_x L, G = q_y L, H = p L,
// ψ₁ = q_x M_x + q_y M_y + p L and ψ = q_x L_x + q_y L_y + p V (uniform loads), as
//   4πG u_x = 2 ∂F/∂z − ∂H/∂x + 2ν ∂ψ₁/∂x − z ∂ψ/∂x
//   4πG u_y = 2 ∂G/∂z − ∂H/∂y + 2ν ∂ψ₁/∂y − z ∂ψ/∂y
//   4πG u_z = ∂H/∂z + (1 − 2ν) ψ − z ∂ψ/∂z.
// The gradient differentiates these once more (z also explicitly). Derivatives without a
// corner function follow from ∂_z L = V, ∂_z M = L and harmonicity of V, L, M:
//   M_xxx = −M_xyy − V_x, M_yyy = −M_xxy − V_y, L_xxx = −L_xyy − V_xz, L_yyy = −L_xxy − V_yz,
//   V_zz = −V_xx − V_yy.
// Summing the diagonal gives 4πG div u = 2(1 − 2ν) Ψ with Ψ = q_x V_x + q_y V_y + p V_z, so
// Hooke's law σ = G(∇u + ∇uᵀ) + λ div u I becomes σ = (D + Dᵀ)/(4π) + (ν/π) Ψ I with D = 4πG ∇u:
// the stresses do not depend on G, and ν = ½ needs no special case.

#include "post/half_space_response.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::post {

namespace {

constexpr double kPi = 3.14159265358979323846;

}  // namespace

HalfSpaceResponse response_from_sums(const CornerSums& s, double z, double g, double nu) {
  const CornerValues& X = s.x;
  const CornerValues& Y = s.y;
  const CornerValues& N = s.n;
  // Derived derivatives (see above), per load component.
  auto mxxx = [](const CornerValues& c) { return -c[kMxyy] - c[kVx]; };
  auto myyy = [](const CornerValues& c) { return -c[kMxxy] - c[kVy]; };
  auto lxxx = [](const CornerValues& c) { return -c[kLxyy] - c[kVxz]; };
  auto lyyy = [](const CornerValues& c) { return -c[kLxxy] - c[kVyz]; };
  auto vzz = [](const CornerValues& c) { return -c[kVxx] - c[kVyy]; };
  const double nu2 = 2.0 * nu, c12 = 1.0 - 2.0 * nu;

  // 4πG u
  std::array<double, 3> U{};
  U[0] =
      2.0 * X[kV] - N[kLx] + nu2 * (X[kMxx] + Y[kMxy] + N[kLx]) - z * (X[kLxx] + Y[kLxy] + N[kVx]);
  U[1] =
      2.0 * Y[kV] - N[kLy] + nu2 * (X[kMxy] + Y[kMyy] + N[kLy]) - z * (X[kLxy] + Y[kLyy] + N[kVy]);
  U[2] = N[kV] + c12 * (X[kLx] + Y[kLy] + N[kV]) - z * (X[kVx] + Y[kVy] + N[kVz]);

  // D = 4πG ∇u, D[i][j] = 4πG ∂u_i/∂x_j
  Matrix3 D{};
  D[0][0] = 2.0 * X[kVx] - N[kLxx] + nu2 * (mxxx(X) + Y[kMxxy] + N[kLxx]) -
            z * (lxxx(X) + Y[kLxxy] + N[kVxx]);
  D[0][1] = 2.0 * X[kVy] - N[kLxy] + nu2 * (X[kMxxy] + Y[kMxyy] + N[kLxy]) -
            z * (X[kLxxy] + Y[kLxyy] + N[kVxy]);
  D[0][2] = 2.0 * X[kVz] - N[kVx] - c12 * (X[kLxx] + Y[kLxy] + N[kVx]) -
            z * (X[kVxx] + Y[kVxy] + N[kVxz]);
  D[1][0] = 2.0 * Y[kVx] - N[kLxy] + nu2 * (X[kMxxy] + Y[kMxyy] + N[kLxy]) -
            z * (X[kLxxy] + Y[kLxyy] + N[kVxy]);
  D[1][1] = 2.0 * Y[kVy] - N[kLyy] + nu2 * (X[kMxyy] + myyy(Y) + N[kLyy]) -
            z * (X[kLxyy] + lyyy(Y) + N[kVyy]);
  D[1][2] = 2.0 * Y[kVz] - N[kVy] - c12 * (X[kLxy] + Y[kLyy] + N[kVy]) -
            z * (X[kVxy] + Y[kVyy] + N[kVyz]);
  D[2][0] = N[kVx] + c12 * (X[kLxx] + Y[kLxy] + N[kVx]) - z * (X[kVxx] + Y[kVxy] + N[kVxz]);
  D[2][1] = N[kVy] + c12 * (X[kLxy] + Y[kLyy] + N[kVy]) - z * (X[kVxy] + Y[kVyy] + N[kVyz]);
  const double psi = X[kVx] + Y[kVy] + N[kVz];
  D[2][2] = N[kVz] + c12 * psi - psi - z * (X[kVxz] + Y[kVyz] + vzz(N));

  HalfSpaceResponse r;
  const double to_u = 1.0 / (4.0 * kPi * g);
  for (int i = 0; i < 3; ++i)
    r.u[static_cast<std::size_t>(i)] = U[static_cast<std::size_t>(i)] * to_u;
  const double lame = nu / kPi * psi;
  for (std::size_t i = 0; i < 3; ++i) {
    for (std::size_t j = 0; j < 3; ++j) {
      r.grad[i][j] = D[i][j] * to_u;
      r.stress[i][j] = (D[i][j] + D[j][i]) / (4.0 * kPi) + (i == j ? lame : 0.0);
    }
  }
  return r;
}

void add_corner(CornerSums& sums, double a, double b, double z, const Traction& w) {
  const CornerValues c = corner_values(a, b, z);
  for (std::size_t k = 0; k < kCornerCount; ++k) {
    sums.x[k] += w.px * c[k];
    sums.y[k] += w.py * c[k];
    sums.n[k] += w.pn * c[k];
  }
}

HalfSpaceResponse rectangle_response(double x, double y, double z, double x0, double x1, double y0,
                                     double y1, const Traction& t, double g, double nu) {
  const double size = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
  const double zz = std::max(z, kMinimumRelativeDepth * size);
  const Traction minus{-t.px, -t.py, -t.pn};
  CornerSums s;
  // ⟦F⟧ = F(x−x0, y−y0) − F(x−x0, y−y1) − F(x−x1, y−y0) + F(x−x1, y−y1)
  add_corner(s, x - x0, y - y0, zz, t);
  add_corner(s, x - x0, y - y1, zz, minus);
  add_corner(s, x - x1, y - y0, zz, minus);
  add_corner(s, x - x1, y - y1, zz, t);
  return response_from_sums(s, zz, g, nu);
}

}  // namespace rollcontact::post
