// Modified FaStrip (spec/physics.md §11.4).

#include "simplified/fastrip.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rollcontact::simplified {

namespace {
constexpr double pi = std::numbers::pi;
}

void fastrip_correction(const FastripInput& in, SimplifiedFields& fields) {
  const Grid& grid = in.grid;
  const double a = in.ellipse.a, b = in.ellipse.b;
  if (!(a > 0.0) || !(b > 0.0) || !(in.fn > 0.0) || !(in.mu > 0.0)) return;
  const double p0 = 1.5 * in.fn / (pi * a * b);
  const double mup0 = in.mu * p0;
  // For χ = π the problem is the mirror image (x → −x) of one with χ = 0, in which ξ and φ
  // change sign and p_x is mirrored back at the end.
  const double s = std::cos(in.chi) >= 0.0 ? 1.0 : -1.0;
  const KalkerCoefficients& c = in.coefficients;
  const double ksi = -2.0 * in.g * (1.0 - in.nu) * c.c11 * s * in.creepages.ksi / (mup0 * pi * pi);
  const double eta = -2.0 * in.g * (1.0 - in.nu) * c.c22 * in.creepages.eta / (mup0 * pi * pi);
  const double phi =
      -3.0 * in.g * std::sqrt(a * b) * c.c23 * s * in.creepages.phi / (2.0 * mup0 * pi);

  for (int iy = 0; iy < grid.my; ++iy) {
    int first = -1, last = -1;
    for (int ix = 0; ix < grid.mx; ++ix) {
      if (!(in.pn[grid.index(ix, iy)] > 0.0)) continue;
      if (first < 0) first = ix;
      last = ix;
    }
    if (first < 0) continue;
    const double aj = 0.5 * (last - first + 1) * grid.dx;
    const double xc = 0.5 * (grid.x_centre(first) + grid.x_centre(last));
    const double yj = grid.y_centre(iy);

    // Half the slip length d_j: the adhesion zone is the circle-shaped Carter zone
    // x′ ∈ [−a_j + 2d_j, a_j] at the leading edge.
    bool full_slip = std::abs(phi - 1.0) <= 1e-6;
    double dj = 0.0;
    const double ksi_y = ksi - phi * yj / a;
    if (!full_slip) {
      const double d = eta * eta + (1.0 - phi * phi) * ksi_y * ksi_y;
      if (d >= 0.0) {
        dj = (std::sqrt(d) + eta * phi) / (1.0 - phi * phi) * a / (1.0 - in.nu);
        full_slip = dj < 0.0;
      } else {
        full_slip = true;
      }
    }
    double kappa = 0.0, lambda = 0.0, lambda_p = 0.0;
    if (!full_slip) {
      const double eta_d = eta + phi * dj / a;
      const double nn = std::hypot(ksi_y, eta_d);
      if (nn > 0.0) {
        kappa = ksi_y / nn;
        lambda = eta_d / nn;
      }
      lambda_p = lambda - phi;
    }

    // Strip tractions in the adhesion zone; the row is corrected only if they respect the bound.
    bool admissible = true;
    for (int ix = first; ix <= last && admissible && !full_slip; ++ix) {
      if (!(in.pn[grid.index(ix, iy)] > 0.0)) continue;
      const double x = s * (grid.x_centre(ix) - xc);
      if (!(x > -aj + 2.0 * dj)) continue;
      const double qc = std::sqrt(std::max(0.0, aj * aj - x * x)) / a;
      const double qa = std::sqrt(std::max(0.0, (aj - dj) * (aj - dj) - (x - dj) * (x - dj))) / a;
      const double fx = kappa * (qc - qa), fy = lambda * qc - lambda_p * qa;
      admissible = fx * fx + fy * fy <= 1.0;
    }
    if (!admissible) continue;

    for (int ix = first; ix <= last; ++ix) {
      const std::size_t i = grid.index(ix, iy);
      if (!(in.pn[i] > 0.0)) continue;
      const double x = s * (grid.x_centre(ix) - xc);
      if (!full_slip && x > -aj + 2.0 * dj) {
        const double qc = std::sqrt(std::max(0.0, aj * aj - x * x)) / a;
        const double qa = std::sqrt(std::max(0.0, (aj - dj) * (aj - dj) - (x - dj) * (x - dj))) / a;
        fields.px[i] = s * mup0 * kappa * (qc - qa);
        fields.py[i] = mup0 * (lambda * qc - lambda_p * qa);
        fields.state[i] = ElementState::Adhesion;
      } else {
        const double bound = in.mu * in.pn[i];
        const double norm = std::hypot(fields.px[i], fields.py[i]);
        if (norm > 0.0) {
          fields.px[i] *= bound / norm;
          fields.py[i] *= bound / norm;
        }
        fields.state[i] = ElementState::Slip;
      }
    }
    // Displacements of the corrected row follow its tractions, u = L·p. The slip keeps the
    // Fastsim value in slip elements (0 where Fastsim had adhesion), as CONTACT reports it (its
    // frictional power depends on this); adhesion has no slip.
    for (int ix = first; ix <= last; ++ix) {
      const std::size_t i = grid.index(ix, iy);
      if (!(in.pn[i] > 0.0)) continue;
      fields.ux[i] = in.flex.l1 * fields.px[i];
      fields.uy[i] = in.flex.l2 * fields.py[i];
      if (fields.state[i] != ElementState::Slip) fields.sx[i] = fields.sy[i] = 0.0;
    }
  }
}

}  // namespace rollcontact::simplified
