#pragma once
// ProfileCurve: a rail or wheel profile as the smooth curve all wheel/rail geometry is evaluated
// on (spec/physics.md §13.1, inp-format.md §8.3 steps 2 and 9): zig-zags removed, split into
// sections at kinks, each section a parametric natural cubic smoothing spline y(s), z(s) over
// the chord length s. Built once per profile; evaluation is cheap and thread-safe.

#include <cmath>
#include <cstddef>
#include <vector>

#include "rollcontact/model/wheelrail.hpp"

namespace rollcontact::wheelrail {

/// A point of the curve: position [mm], slope dz/dy [-] and the curve parameter s [mm].
/// Where the last at_y() of a run of nearby queries ended (segment and local parameter): the
/// next query starts there instead of searching and starting from the chord.
struct CurveHint {
  std::size_t segment = static_cast<std::size_t>(-1);
  double t = 0.0;
};

struct CurvePoint {
  double y = 0.0, z = 0.0;
  double dz_dy = 0.0;
  double s = 0.0;
  bool found = false;  ///< false: y lies outside the profile
  /// The unit tangent (dy/ds, dz/ds) along the curve parameter: set by at_s() only (a flange's
  /// vertical tangent has no finite dz/dy).
  double dy_ds = 0.0, dz_ds = 0.0;
};

class ProfileCurve {
 public:
  /// The profile's points (canonical form) become the curve. `upper_surface`: when several parts
  /// of the curve lie above one y, at_y() returns the one with the smallest z (a rail's top);
  /// otherwise the largest z (a wheel's running surface). Throws GeometryError naming the
  /// profile file when too many points are removed or fewer than two remain.
  ProfileCurve(const model::WheelRailProfile& profile, bool upper_surface);
  /// Same points, rotated by `roll_rad` about the x-axis and shifted by (dy, dz) first (a rail
  /// placed in the track).
  ProfileCurve(const model::WheelRailProfile& profile, bool upper_surface, double roll_rad,
               double dy_mm, double dz_mm);

  /// The surface point above (or below) lateral position y.
  CurvePoint at_y(double y) const;
  /// Same, for a run of nearby queries (Newton iterations, neighbouring elements): the same
  /// point to the solver's tolerance (1e-12 relative in y), found from the hint's segment.
  CurvePoint at_y(double y, CurveHint& hint) const;
  /// Where a line meets the curve: (y(s), z(s)) = (a(t), b(t)) for the curve parameter s and the
  /// line parameter t, by one Newton iteration in (s, t) that starts at the hint's segment and
  /// parameter (the hint must come from an earlier query) and at t. `line(t, a, da, b, db)`
  /// gives a(t), b(t) and their derivatives. Returns false when the hint is empty, the curve is
  /// not monotone, the iteration leaves the hint's section or does not converge: the caller
  /// then takes the nested way (at_y per step). On success t is the meeting point (|Δt| <
  /// 1e-11) and the hint its segment.
  template <class Line>
  bool meet_line(const Line& line, double& t, CurveHint& hint) const;
  /// The point at curve parameter s (clamped to the curve).
  CurvePoint at_s(double s) const;
  double y_min() const noexcept { return y_min_; }
  double y_max() const noexcept { return y_max_; }
  double length() const noexcept { return s_.empty() ? 0.0 : s_.back(); }
  /// The cleaned node positions (after zig-zag removal), in curve order.
  const std::vector<double>& node_y() const noexcept { return y_; }
  const std::vector<double>& node_z() const noexcept { return z_; }
  const std::vector<double>& node_s() const noexcept { return s_; }
  std::size_t section_count() const noexcept { return section_start_.size(); }

 private:
  void build(std::vector<double> y, std::vector<double> z, const model::WheelRailProfile& p);
  /// y(s), z(s) and derivatives on segment k at local t ∈ [0, h_k].
  void eval_segment(std::size_t k, double t, double& y, double& z, double& dy, double& dz) const;
  CurvePoint solve_in_segment(std::size_t k, double y) const;
  /// Same, starting the Newton iteration at local parameter t0 (< 0: from the chord).
  CurvePoint solve_in_segment(std::size_t k, double y, double t0) const;

  bool upper_ = true;
  bool monotone_ = true;  ///< node y strictly increasing or decreasing over the whole curve
  bool increasing_ = true;
  double y_min_ = 0.0, y_max_ = 0.0;
  std::vector<double> s_, y_, z_, y2_, z2_;  ///< nodes: parameter, fitted values, y'', z''
  std::vector<std::size_t> section_start_;   ///< first node of each section
  std::vector<char> segment_break_;          ///< 1: no spline between node k and k+1 (a kink)
};

template <class Line>
bool ProfileCurve::meet_line(const Line& line, double& t, CurveHint& hint) const {
  std::size_t k = hint.segment;
  if (!monotone_ || y_.size() < 2 || k >= y_.size() - 1 || segment_break_[k]) return false;
  double u = hint.t;  // local parameter on segment k
  for (int it = 0; it < 30; ++it) {
    double y = 0.0, z = 0.0, dy = 0.0, dz = 0.0, a = 0.0, da = 0.0, b = 0.0, db = 0.0;
    eval_segment(k, u, y, z, dy, dz);
    line(t, a, da, b, db);
    // F = (y − a, z − b), J = [[dy, −da], [dz, −db]] in (u, t).
    const double f1 = y - a, f2 = z - b;
    const double det = -dy * db + da * dz;
    if (det == 0.0 || !std::isfinite(det)) return false;
    const double du = (-f1 * -db - -da * -f2) / det;
    const double dt = (dy * -f2 - dz * -f1) / det;
    u += du;
    t += dt;
    // Stay on the section: step to the neighbouring segment when u leaves [0, h_k].
    while (u < 0.0) {
      if (k == 0 || segment_break_[k - 1]) return false;
      --k;
      u += s_[k + 1] - s_[k];
    }
    while (u > s_[k + 1] - s_[k]) {
      if (k + 2 >= s_.size() || segment_break_[k + 1]) return false;
      u -= s_[k + 1] - s_[k];
      ++k;
    }
    // Converged when the step is below 1e-6 mm: Newton's error after it is then of the order
    // of the step squared over the radii of curvature (≥ 1 mm), ≤ 1e-12 mm, far below the
    // 1e-11 mm the steps were once required to reach — which took one more evaluation to
    // confirm. Along a patch row the start extrapolated from three elements is off by 1e-9 to
    // 1e-6 mm (trace_row): one evaluation then suffices for most elements.
    if (std::abs(dt) < 1e-6 && std::abs(du) < 1e-6) {
      hint.segment = k;
      hint.t = u;
      return true;
    }
  }
  return false;
}

}  // namespace rollcontact::wheelrail
