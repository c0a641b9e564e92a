// Undeformed distance h(x, y) of the non-Hertzian geometry options (spec/physics.md §4,
// inp-format.md §4.3), evaluated at element centres because all fields are piecewise constant.

#include <cmath>
#include <cstddef>
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
      throw NotSupportedError(
          "IPLAN=4 (NPATCH rectangles with interaction factors) is not "
          "supported");
    default:
      throw ProblemError("IPLAN must be 1, 2 or 3, got " + std::to_string(g.iplan));
  }
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
    default:
      return true;
  }
}

}  // namespace

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
