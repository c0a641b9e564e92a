#include "elastic/inclination_correction.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstddef>
#include <utility>

#include "rollcontact/errors.hpp"

namespace rollcontact::elastic {

namespace {

/// Row and column (x = 0, s = 1, n = 2) of a component: displacement i due to traction j.
std::pair<int, int> place(Component c) {
  switch (c) {
    case Component::xx:
      return {0, 0};
    case Component::xy:
      return {0, 1};
    case Component::xn:
      return {0, 2};
    case Component::yx:
      return {1, 0};
    case Component::yy:
      return {1, 1};
    case Component::yn:
      return {1, 2};
    case Component::nx:
      return {2, 0};
    case Component::ny:
      return {2, 1};
    case Component::nn:
      return {2, 2};
  }
  return {2, 2};
}

/// M(φ): the turn by φ about x of the (s, n) components.
void turn_matrix(double phi, double (&m)[3][3]) {
  const double c = std::cos(phi), s = std::sin(phi);
  const double t[3][3] = {{1.0, 0.0, 0.0}, {0.0, c, -s}, {0.0, s, c}};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) m[i][j] = t[i][j];
}

void multiply(const double (&l)[3][3], const double (&r)[3][3], double (&out)[3][3]) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double sum = 0.0;
      for (int k = 0; k < 3; ++k) sum += l[i][k] * r[k][j];
      out[i][j] = sum;
    }
}

}  // namespace

double inclination_curvature(const model::InclinationCorrection& correction) {
  const std::vector<double>& y = correction.y_mm;
  const std::vector<double>& a = correction.alpha_rad;
  if (y.empty() || y.size() != a.size())
    throw ProblemError(fmt::format(
        "the inclination correction (C=4) needs a table of positions and inclinations of equal "
        "length, not {} and {}",
        y.size(), a.size()));
  double y_mean = 0.0, a_mean = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    if (!std::isfinite(y[k]) || !std::isfinite(a[k]))
      throw ProblemError(fmt::format(
          "the inclination correction (C=4): entry {} of the table is not finite (y = {}, "
          "alpha = {})",
          k + 1, y[k], a[k]));
    y_mean += y[k];
    a_mean += a[k];
  }
  y_mean /= static_cast<double>(y.size());
  a_mean /= static_cast<double>(y.size());
  double syy = 0.0, sya = 0.0;
  for (std::size_t k = 0; k < y.size(); ++k) {
    syy += (y[k] - y_mean) * (y[k] - y_mean);
    sya += (y[k] - y_mean) * (a[k] - a_mean);
  }
  // All positions equal: one inclination, no change across the rows.
  return syy > 0.0 ? sya / syy : 0.0;
}

void turn_coefficients(int variant, double theta_rad, const double (&a)[3][3], double (&b)[3][3]) {
  double m[3][3];
  switch (variant) {
    case 1:
    case 2:
      turn_matrix(theta_rad, m);
      multiply(a, m, b);
      if (variant == 2) b[0][2] = a[0][2];
      return;
    case 3:
      turn_matrix(theta_rad, m);
      multiply(m, a, b);
      return;
    case 4: {
      double half[3][3], am[3][3];
      turn_matrix(0.5 * theta_rad, half);
      multiply(a, half, am);
      multiply(half, am, b);
      return;
    }
    default:
      throw ProblemError(
          fmt::format("the inclination correction (C=4) has the variants 1 to 4, not {}", variant));
  }
}

CombinedMaterial uncorrected(const CombinedMaterial& material) {
  CombinedMaterial plain = material;
  plain.inclination_variant = 0;
  plain.inclination_curvature_per_mm = 0.0;
  return plain;
}

std::vector<Component> plain_components(const CombinedMaterial& plain) {
  std::vector<Component> cs{Component::xx, Component::xy, Component::yy, Component::nn};
  // Quasi-identical bodies: zero couplings, not tabulated.
  if (is_coupled(plain))
    cs.insert(cs.end(), {Component::xn, Component::yn, Component::nx, Component::ny});
  return cs;
}

std::vector<Kernel> turned_kernels(const std::vector<Component>& cs,
                                   const std::vector<Kernel>& plain, const Grid& grid,
                                   const CombinedMaterial& material, double shift_y) {
  const bool coupled = plain.size() == 8;
  const Kernel zero(grid.mx, grid.my);
  const std::vector<Kernel>& k = plain;
  const Kernel* comp[3][3] = {{&k[0], &k[1], coupled ? &k[4] : &zero},
                              {&k[1], &k[2], coupled ? &k[5] : &zero},
                              {coupled ? &k[6] : &zero, coupled ? &k[7] : &zero, &k[3]}};
  std::vector<Kernel> out(cs.size(), Kernel(grid.mx, grid.my));
  const double curvature = material.inclination_curvature_per_mm;
  for (int diy = -(grid.my - 1); diy <= grid.my - 1; ++diy) {
    // θ = α_J − α_I = −c₁·(y_I − y_J), the observation point I moved by the shift.
    const double theta = -curvature * (diy * grid.dy + shift_y);
    for (int dix = -(grid.mx - 1); dix <= grid.mx - 1; ++dix) {
      double a[3][3], b[3][3];
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a[i][j] = comp[i][j]->at(dix, diy);
      turn_coefficients(material.inclination_variant, theta, a, b);
      for (std::size_t q = 0; q < cs.size(); ++q) {
        const auto [i, j] = place(cs[q]);
        out[q].at(dix, diy) = b[i][j];
      }
    }
  }
  return out;
}

std::vector<Kernel> inclination_corrected_kernels(const std::vector<Component>& cs,
                                                  const Grid& grid,
                                                  const CombinedMaterial& material, double shift_x,
                                                  double shift_y) {
  const CombinedMaterial plain = uncorrected(material);
  return turned_kernels(cs, make_kernels(plain_components(plain), grid, plain, shift_x, shift_y),
                        grid, material, shift_y);
}

}  // namespace rollcontact::elastic
