#pragma once
// The lateral iteration of the massless rail (F=3, spec/wheelrail-advanced.md §2.4, §2.6): the
// rail's lateral deflection δy [mm] at which r(δy) = F_y(tr)(δy) − ky·δy + fy = 0 [N]. Each
// evaluation of r is a complete wheel/rail solve (with its own vertical iteration), so the
// iteration keeps their number small: a first step from the spring alone, secant steps until
// the root is bracketed, then a safeguarded secant/bisection (Brent-type) inside the bracket.
// The 2×2 power-law Newton of §2.5 is not used (docs/decisions.md, "Massless rail").

#include <functional>
#include <string>

namespace rollcontact::wheelrail {

struct LateralRailSettings {
  double stiffness_N_per_mm = 0.0;  ///< ky: the residual falls at least this fast with δy
  double first_step_mm = 1.0;       ///< DYSTEP0: the first step when ky = 0 or r/ky exceeds 3 mm
  double tolerance_N = 1e-6;        ///< stop when |r| < this
  double tolerance_mm = 1e-5;       ///< stop when the bracket (or a step) is narrower [mm]
  int max_iterations = 30;          ///< MAXNR: evaluations of r, the first one included
  double start_mm = 0.0;            ///< first iterate
};

struct LateralRailResult {
  double dy_mm = 0.0;       ///< the last iterate (whose solve stands)
  double residual_N = 0.0;  ///< r there
  int iterations = 0;       ///< evaluations of r
  bool converged = false;   ///< |r| < tolerance_N or the bracket narrower than tolerance_mm
  std::string message;      ///< why not converged, or a jump in F_y found inside the bracket
};

/// `residual(dy)` solves the contact problem with the rail deflected by dy and returns r [N]; the
/// last call is the one whose results stand.
LateralRailResult solve_lateral_rail(const LateralRailSettings& settings,
                                     const std::function<double(double)>& residual);

}  // namespace rollcontact::wheelrail
