#include "wheelrail/massless_rail.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace rollcontact::wheelrail {

namespace {

struct Iterate {
  double x = 0.0, r = 0.0;  ///< δy [mm], residual [N]
};

/// The next iterate while every residual has the same sign (spec §2.6, lateral unknown): the
/// secant over the whole table, 5 % beyond its root, at least 0.2 and at most 1.5 table widths
/// beyond the end on the root's side. The residual is expected to fall with δy (the spring, and
/// a contact force that eases as the rail gives way); a measured rise is believed.
double outward_step(const std::vector<Iterate>& sorted) {
  const Iterate& a = sorted.front();
  const Iterate& b = sorted.back();
  const double width = b.x - a.x;
  const double slope = (b.r - a.r) / width;
  const bool falling = !(slope > 0.0);
  const int dir = (a.r > 0.0) == falling ? 1 : -1;
  const Iterate& end = dir > 0 ? b : a;
  double dist = slope != 0.0 && std::isfinite(slope) ? 1.05 * std::abs(end.r / slope) : width;
  dist = std::clamp(dist, 0.2 * width, 1.5 * width);
  return end.x + dir * dist;
}

/// Inside the bracket [lo, hi] (residuals of opposite sign): the secant through the two latest
/// iterates when it falls inside, else the secant through the bracket's ends, else bisection —
/// also when the bracket has not halved in two steps (Brent's safeguard against one-sided
/// convergence). A step shorter than tol/2 from the latest iterate is lengthened to tol/2 towards
/// the bracket's far end so that the next bracket can be narrower than tol.
double bracketed_step(const Iterate& lo, const Iterate& hi, const Iterate& latest,
                      const Iterate& previous, bool stalling, double tol) {
  const double width = hi.x - lo.x;
  auto inside = [&](double x) { return x > lo.x && x < hi.x; };
  double x = std::numeric_limits<double>::quiet_NaN();
  if (latest.r != previous.r)
    x = latest.x - latest.r * (latest.x - previous.x) / (latest.r - previous.r);
  if (!inside(x)) x = lo.x - lo.r * width / (hi.r - lo.r);
  if (stalling || !inside(x)) x = 0.5 * (lo.x + hi.x);
  if (std::abs(x - latest.x) < 0.5 * tol) {
    const double far = std::abs(hi.x - latest.x) > std::abs(latest.x - lo.x) ? hi.x : lo.x;
    x = latest.x + std::copysign(0.5 * tol, far - latest.x);
  }
  return x;
}

}  // namespace

LateralRailResult solve_lateral_rail(const LateralRailSettings& st,
                                     const std::function<double(double)>& residual) {
  LateralRailResult res;
  std::vector<Iterate> table;  // sorted by x
  Iterate latest{st.start_mm, 0.0}, previous;
  double width_before = std::numeric_limits<double>::infinity(), width_last = width_before;
  double x = st.start_mm;
  const int max_it = std::max(st.max_iterations, 1);
  for (int k = 0; k < max_it; ++k) {
    previous = latest;
    latest = {x, residual(x)};
    res.dy_mm = x;
    res.residual_N = latest.r;
    res.iterations = k + 1;
    if (!std::isfinite(latest.r)) {
      res.message = fmt::format("the lateral rail balance is not finite at dy_defl = {:g} mm", x);
      return res;
    }
    if (std::abs(latest.r) < st.tolerance_N) {
      res.converged = true;
      return res;
    }
    table.insert(std::upper_bound(table.begin(), table.end(), latest,
                                  [](const Iterate& a, const Iterate& b) { return a.x < b.x; }),
                 latest);
    if (k == 0) {
      // The spring alone: a contact force that eases as the rail gives way makes this step
      // overshoot the root, so the second iterate usually brackets it. A step longer than
      // kMaxFirstStepMm is DYSTEP0 instead (wheelrail-advanced.md §2.5: early steps are at most
      // 3 mm): the contact changes within millimetres, and a residual of 3.5 MN on a 1 kN/mm
      // rail (a random case) moved the rail by 3.5 m and left a bracket that MAXNR bisections
      // could not close.
      constexpr double kMaxFirstStepMm = 3.0;
      const double spring_step = st.stiffness_N_per_mm > 0.0
                                     ? latest.r / st.stiffness_N_per_mm
                                     : std::numeric_limits<double>::infinity();
      x += std::abs(spring_step) <= kMaxFirstStepMm ? spring_step
                                                    : std::copysign(st.first_step_mm, latest.r);
      continue;
    }
    // The bracket: a sign change between neighbours in the table; with several (a residual that
    // is not monotonic) the one nearest the latest iterate.
    const auto n = static_cast<std::ptrdiff_t>(table.size());
    std::ptrdiff_t at = 0;
    while (table[static_cast<std::size_t>(at)].x != latest.x) ++at;
    std::ptrdiff_t best = -1, best_distance = n;
    for (std::ptrdiff_t i = 0; i + 1 < n; ++i) {
      const auto u = static_cast<std::size_t>(i);
      if ((table[u].r < 0.0) == (table[u + 1].r < 0.0)) continue;
      const std::ptrdiff_t d = std::min(std::abs(i - at), std::abs(i + 1 - at));
      if (d < best_distance) best = i, best_distance = d;
    }
    if (best < 0) {
      if (std::abs(latest.x - previous.x) < st.tolerance_mm) {
        res.converged = true;  // the step is below the tolerance on δy
        return res;
      }
      x = outward_step(table);
      continue;
    }
    const Iterate& lo = table[static_cast<std::size_t>(best)];
    const Iterate& hi = table[static_cast<std::size_t>(best) + 1];
    const double width = hi.x - lo.x;
    if (width < st.tolerance_mm) {
      res.converged = true;
      // A residual that changes by far more across the bracket than the spring and the table's
      // slope explain: F_y jumps there (contact switching), and δy sits at the jump.
      const double slope =
          std::abs((table.back().r - table.front().r) / (table.back().x - table.front().x));
      if (std::abs(hi.r - lo.r) > 100.0 * std::max(slope, st.stiffness_N_per_mm) * width)
        res.message = fmt::format(
            "the lateral force jumps by {:.4g} N within dy_defl {:.6g}..{:.6g} mm (contact "
            "switching): the rail balance is left with {:.4g} N",
            hi.r - lo.r, lo.x, hi.x, latest.r);
      return res;
    }
    const bool stalling = width > 0.5 * width_before;
    width_before = width_last;
    width_last = width;
    x = bracketed_step(lo, hi, latest, previous, stalling, st.tolerance_mm);
    if (stalling) width_before = width_last = std::numeric_limits<double>::infinity();
  }
  res.message = fmt::format(
      "the massless rail's lateral balance did not converge in MAXNR = {} iterations "
      "(residual {:.4g} N at dy_defl = {:.6g} mm)",
      max_it, res.residual_N, res.dy_mm);
  return res;
}

}  // namespace rollcontact::wheelrail
