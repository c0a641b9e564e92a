#pragma once
// ProfileCurve: a rail or wheel profile as the smooth curve all wheel/rail geometry is evaluated
// on (spec/physics.md §13.1, inp-format.md §8.3 steps 2 and 9): zig-zags removed, split into
// sections at kinks, each section a parametric natural cubic smoothing spline y(s), z(s) over
// the chord length s. Built once per profile; evaluation is cheap and thread-safe.

#include <vector>

#include "rollcontact/model/wheelrail.hpp"

namespace rollcontact::wheelrail {

/// A point of the curve: position [mm], slope dz/dy [-] and the curve parameter s [mm].
struct CurvePoint {
  double y = 0.0, z = 0.0;
  double dz_dy = 0.0;
  double s = 0.0;
  bool found = false;  ///< false: y lies outside the profile
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

  bool upper_ = true;
  bool monotone_ = true;  ///< node y strictly increasing or decreasing over the whole curve
  bool increasing_ = true;
  double y_min_ = 0.0, y_max_ = 0.0;
  std::vector<double> s_, y_, z_, y2_, z2_;  ///< nodes: parameter, fitted values, y'', z''
  std::vector<std::size_t> section_start_;   ///< first node of each section
  std::vector<char> segment_break_;          ///< 1: no spline between node k and k+1 (a kink)
};

}  // namespace rollcontact::wheelrail
