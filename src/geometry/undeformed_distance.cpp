// Undeformed distance h(x, y) of the non-Hertzian geometry options (spec/physics.md §4,
// inp-format.md §4.3), evaluated at element centres because all fields are piecewise constant.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "geometry/discretisation.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::geometry {

namespace {

void require_count(const std::vector<double>& v, std::size_t n, const char* what) {
  if (v.size() < n) {
    throw ProblemError(std::string(what) + " needs " + std::to_string(n) + " values, got " +
                       std::to_string(v.size()));
  }
}

/// IPLAN=4: NPATCH rectangles with ordered limits and factors f_ij in [0, 1] (a factor above 1
/// or below 0 would make the influence operator indefinite).
void validate_patches(const UndeformedDistance& g) {
  if (g.npatch < 1 || g.npatch > kMaxPlanformPatches) {
    throw ProblemError("IPLAN=4: NPATCH = " + std::to_string(g.npatch) + " must lie in 1.." +
                       std::to_string(kMaxPlanformPatches));
  }
  const auto n = static_cast<std::size_t>(g.npatch);
  require_count(g.planform, 4 * n, "IPLAN=4 (NPATCH rectangles) XL XH YL YH per patch");
  for (std::size_t i = 0; i < 4 * n; i += 2) {
    if (g.planform[i] > g.planform[i + 1]) {
      throw ProblemError("IPLAN=4: each lower limit must be <= its upper limit (patch " +
                         std::to_string(i / 4 + 1) + ")");
    }
  }
  require_count(g.patch_factors, n * (n - 1) / 2, "IPLAN=4 factors f12 f13 ... f23 ...");
  for (double f : g.patch_factors) {
    if (!(f >= 0.0 && f <= 1.0)) {
      throw ProblemError("IPLAN=4: interaction factor " + std::to_string(f) +
                         " must lie in [0, 1]");
    }
  }
}

/// IBASE 2: piecewise-linear profile through samples at y_k = y1 + k·dy1 (k = 0..NN−1);
/// outside the sampled range the first/last segment is extended (linear extrapolation).
double profile_value(const UndeformedDistance& g, double y) {
  const auto nn = static_cast<std::ptrdiff_t>(g.coeffs.size());
  const double t = (y - g.y1) / g.dy1;
  auto k = static_cast<std::ptrdiff_t>(std::floor(t));
  if (k < 0) k = 0;
  if (k > nn - 2) k = nn - 2;
  const double b0 = g.coeffs[static_cast<std::size_t>(k)];
  const double b1 = g.coeffs[static_cast<std::size_t>(k + 1)];
  return b0 + (t - static_cast<double>(k)) * (b1 - b0);
}

double base_value(const UndeformedDistance& g, double x, double y) {
  const std::vector<double>& b = g.coeffs;
  switch (g.ibase) {
    case 1:
      return b[0] * x * x + b[1] * x * y + b[2] * y * y + b[3] * x + b[4] * y + b[5];
    case 2:
      return profile_value(g, y) + (x - g.xm) * (x - g.xm) / (2.0 * g.rm);
    case 3:
      return b[0] * std::sin(b[1] * (x - b[2])) - b[3] * std::sin(b[4] * (x - b[5])) +
             x * x / b[6] + y * y / b[7];
    default:
      return 0.0;  // unreachable: checked in validate_geometry
  }
}

void validate_geometry(const Grid& grid, const UndeformedDistance& g) {
  switch (g.ibase) {
    case 1:
      require_count(g.coeffs, 6, "IBASE=1 (quadratic) B1..B6");
      break;
    case 2:
      if (g.coeffs.size() < 2) throw ProblemError("IBASE=2 (profile) needs NN >= 2 samples");
      if (!(g.dy1 > 0.0)) throw ProblemError("IBASE=2 (profile) needs DY1 > 0");
      if (g.rm == 0.0) {
        throw ProblemError("IBASE=2 (profile) needs RM != 0 (use a large RM for a flat x-profile)");
      }
      break;
    case 3:
      require_count(g.coeffs, 8, "IBASE=3 (sines) B1..B8");
      if (g.coeffs[6] == 0.0 || g.coeffs[7] == 0.0) {
        throw ProblemError(
            "IBASE=3 (sines): B7 and B8 must be non-zero (x²/B7 + y²/B8; use a "
            "large value for a flat direction)");
      }
      break;
    case 9:
      if (g.values.size() != grid.size()) {
        throw ProblemError("IBASE=9 needs MX*MY = " + std::to_string(grid.size()) +
                           " values of h, got " + std::to_string(g.values.size()));
      }
      break;
    default:
      throw ProblemError("IBASE must be 1, 2, 3 or 9, got " + std::to_string(g.ibase));
  }
  switch (g.iplan) {
    case 1:
      break;
    case 2:
      require_count(g.planform, 6, "IPLAN=2 (quadratic planform) PL1..PL6");
      break;
    case 3: {
      require_count(g.planform, 8, "IPLAN=3 (two rectangles) XL1 XH1 YL1 YH1 XL2 XH2 YL2 YH2");
      const std::vector<double>& p = g.planform;
      for (std::size_t i = 0; i < 8; i += 2) {
        if (p[i] > p[i + 1]) {
          throw ProblemError("IPLAN=3: each lower limit must be <= its upper limit");
        }
      }
      break;
    }
    case 4:
      validate_patches(g);
      break;
    default:
      throw ProblemError("IPLAN must be 1, 2, 3 or 4, got " + std::to_string(g.iplan));
  }
}

/// IPLAN=4: the first rectangle (XL XH YL YH, borders inclusive) containing (x, y), or −1.
int rectangle_of(const UndeformedDistance& g, double x, double y) {
  const std::vector<double>& p = g.planform;
  for (int k = 0; k < g.npatch; ++k) {
    const std::size_t o = 4 * static_cast<std::size_t>(k);
    if (x >= p[o] && x <= p[o + 1] && y >= p[o + 2] && y <= p[o + 3]) return k;
  }
  return -1;
}

/// True when the element centre (x, y) belongs to the planform.
bool in_planform(const UndeformedDistance& g, double x, double y) {
  const std::vector<double>& p = g.planform;
  switch (g.iplan) {
    case 2:  // excluded where the quadratic form is >= 0
      return p[0] * x * x + p[1] * x * y + p[2] * y * y + p[3] * x + p[4] * y + p[5] < 0.0;
    case 3: {  // union of two closed rectangles
      const bool in1 = x >= p[0] && x <= p[1] && y >= p[2] && y <= p[3];
      const bool in2 = x >= p[4] && x <= p[5] && y >= p[6] && y <= p[7];
      return in1 || in2;
    }
    case 4:  // union of NPATCH closed rectangles
      return rectangle_of(g, x, y) >= 0;
    default:
      return true;
  }
}

}  // namespace

PlanformParts planform_parts(const Grid& grid, const UndeformedDistance& geometry) {
  PlanformParts parts;
  if (geometry.iplan != 4 || geometry.npatch < 2) return parts;
  validate_patches(geometry);
  bool attenuated = false;
  for (double f : geometry.patch_factors) attenuated = attenuated || f != 1.0;
  if (!attenuated) return parts;
  const int n = geometry.npatch;
  parts.n_parts = n;
  parts.factor.assign(static_cast<std::size_t>(n) * static_cast<std::size_t>(n), 1.0);
  std::size_t k = 0;  // f12 f13 ... f1n f23 ...
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b, ++k) {
      const double f = geometry.patch_factors[k];
      parts.factor[static_cast<std::size_t>(a * n + b)] = f;
      parts.factor[static_cast<std::size_t>(b * n + a)] = f;
    }
  parts.part.assign(grid.size(), 0);
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix) {
      const int r = rectangle_of(geometry, grid.x_centre(ix), grid.y_centre(iy));
      parts.part[grid.index(ix, iy)] = static_cast<std::uint8_t>(r < 0 ? 0 : r);
    }
  return parts;
}

std::vector<double> undeformed_distance(const Grid& grid, const UndeformedDistance& geometry) {
  validate_geometry(grid, geometry);
  std::vector<double> h(grid.size());
  bool any_included = false;
  for (int iy = 0; iy < grid.my; ++iy) {
    const double y = grid.y_centre(iy);
    for (int ix = 0; ix < grid.mx; ++ix) {
      const double x = grid.x_centre(ix);
      const std::size_t i = grid.index(ix, iy);
      if (!in_planform(geometry, x, y)) {
        h[i] = excluded_distance;
        continue;
      }
      any_included = true;
      h[i] = geometry.ibase == 9 ? geometry.values[i] : base_value(geometry, x, y);
    }
  }
  if (!any_included) {
    throw ProblemError("the planform (IPLAN=" + std::to_string(geometry.iplan) +
                       ") excludes every element of the potential contact area");
  }
  return h;
}

}  // namespace rollcontact::geometry
