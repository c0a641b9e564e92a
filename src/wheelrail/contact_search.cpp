#include "wheelrail/contact_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "wheelrail/golden_section.hpp"
#include "wheelrail/sliced_locus.hpp"

namespace rollcontact::wheelrail {

namespace {

constexpr double kNoWheel = 1e30;
/// The most lateral gap samples of a contact search (0.3·DS apart: 2,500 at DS = 0.2 mm on a
/// 150 mm rail profile); reached only for DS below 2 µm.
constexpr std::size_t kMaxGapSamples = 250000;

/// A rail that varies along x (a roller, a sliced rail): the wheel-frame x of the locus point on
/// the wheel's circle at profile point w (radius r), where the wheel's surface normal n (track
/// frame) is parallel to the rail's, n_x + (∂z_rail/∂x)·n_z = 0 — the track's condition n_x = 0
/// with the rail's slope along x (spec/wheelrail-advanced.md §4.2). Solved exactly by secants
/// from the track's locus x0 (a fixed-point iteration would diverge for a roller smaller than
/// the wheel).
double varying_rail_locus_x(const PlacedProfiles& prof, const WheelsetPose& pose, double y_ws,
                            const CurvePoint& w, double r, double x0, double x_limit) {
  const Mat3& R = pose.wheel_rotation;
  const auto condition = [&](double x, bool& ok) {
    const double c = std::sqrt(std::max(r * r - x * x, 0.0));
    const Vec3 pt = pose.wheel_centre + R * Vec3{x, y_ws, c};
    const RailSurfacePoint rs = prof.rail_surface_at(pt.x, pt.y);
    ok = rs.found;
    const Vec3 n = R * Vec3{x / r, -w.dz_dy, c / r};
    return n.x + rs.dz_dx * n.z;
  };
  bool ok = false;
  double xa = x0, fa = condition(xa, ok);
  if (!ok) return x0;
  double xb = x0 + 1e-3 * r, fb = condition(xb, ok);
  for (int it = 0; it < 30 && ok && fb != fa; ++it) {
    const double xc = std::clamp(xb - fb * (xb - xa) / (fb - fa), -x_limit, x_limit);
    xa = xb;
    fa = fb;
    xb = xc;
    fb = condition(xb, ok);
    if (std::abs(xb - xa) < 1e-10) break;
  }
  return ok ? xb : x0;
}

/// The contact locus sampled along the wheel profile and mapped onto the lateral grid: where
/// several locus segments cover one grid position, the deepest wheel point counts.
void fill_locus(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                const WheelsetPose& pose, GapSamples& s) {
  GapFunction& g = s.base;
  std::vector<double>& z_locus = s.locus_z;
  const std::size_t n = g.gap.size();
  z_locus.assign(n, -kNoWheel);
  g.x_locus.assign(n, 0.0);
  g.wheel_y.assign(n, 0.0);
  const Mat3& R = pose.wheel_rotation;
  const double r_nom = p.wheelset.nominal_radius_mm;
  const double y_off = prof.wheel_y_offset_mm(), r0 = prof.wheel_r0_mm();
  const ProfileCurve& wheel = prof.wheel();
  const double step = 0.5 * g.dy_mm;
  const auto samples = static_cast<std::size_t>((wheel.y_max() - wheel.y_min()) / step) + 1;
  // The profile's points at the sample positions: the same for every pose of a plain wheel.
  if (prof.wheel_surface() != nullptr || s.wheel_step_mm != step ||
      s.wheel_points.size() != samples + 1) {
    s.wheel_points.clear();
    for (std::size_t k = 0; k <= samples; ++k)
      s.wheel_points.push_back(
          wheel.at_y(std::min(wheel.y_min() + step * static_cast<double>(k), wheel.y_max())));
    s.wheel_step_mm = prof.wheel_surface() != nullptr ? 0.0 : step;
    s.wheel_radius_max_mm = 0.0;
    for (const CurvePoint& w : s.wheel_points)
      if (w.found) s.wheel_radius_max_mm = std::max(s.wheel_radius_max_mm, std::abs(r0 + w.z));
  }
  // Only samples whose locus point can reach the lateral grid [y_0, y_{n−1}] count: a point lies
  // within `reach` of c_y + R11·(y_off + yp) (|x| ≤ r_nom/2, 0 ≤ q_z ≤ r), and a sample outside
  // that band on either side forms segments with its neighbours there that miss the grid. Two
  // samples more on each side; the whole profile for a sliced wheel (its points are searched).
  std::size_t k_begin = 0, k_end = samples;
  if (prof.wheel_surface() == nullptr && R.r[1][1] > 0.5 && n > 0) {
    const double reach = std::abs(R.r[1][0]) * 0.5 * r_nom +
                         std::abs(R.r[1][2]) * s.wheel_radius_max_mm + 2.0 * g.dy_mm;
    const double c_y = pose.wheel_centre.y + R.r[1][1] * y_off;
    const double yp_lo = (g.y(0) - reach - c_y) / R.r[1][1];  // centre(yp) + reach ≥ y_0
    const double yp_hi = (g.y(n - 1) + reach - c_y) / R.r[1][1];
    const double k_lo = std::floor((yp_lo - wheel.y_min()) / step) - 2.0;
    const double k_hi = std::ceil((yp_hi - wheel.y_min()) / step) + 2.0;
    if (k_lo > 0.0) k_begin = std::min(static_cast<std::size_t>(k_lo), samples);
    if (k_hi < static_cast<double>(samples))
      k_end = k_hi < 0.0 ? 0 : static_cast<std::size_t>(k_hi);
  }
  Vec3 prev{};
  double prev_yp = 0.0;
  bool have_prev = false;
  LocusScanSections scan(locus_scan_angles());  // a sliced wheel's scanned cross-sections
  for (std::size_t k = k_begin; k <= k_end; ++k) {
    const double yp = std::min(wheel.y_min() + step * static_cast<double>(k), wheel.y_max());
    const CurvePoint& w = s.wheel_points[k];
    if (!w.found) continue;
    const double r = r0 + w.z;
    double x = (r * w.dz_dy * R.r[0][1] - r_nom * R.r[0][2]) / R.r[0][0];
    x = std::clamp(x, -0.5 * r_nom, 0.5 * r_nom);
    if (prof.rail_varies_along_x())
      x = varying_rail_locus_x(prof, pose, y_off + yp, w, r, x, 0.5 * r_nom);
    const Vec3 q{x, y_off + yp, std::sqrt(std::max(r * r - x * x, 0.0))};
    Vec3 pt = pose.wheel_centre + R * q;
    if (prof.wheel_surface() != nullptr) {
      // Out of round: search the circumference from the round wheel's locus angle.
      const LocusPoint lp = sliced_locus_point(prof, pose, yp, std::atan2(q.x, q.z), &scan);
      if (!lp.found) continue;
      pt = lp.point;
    }
    if (have_prev && pt.y != prev.y) {
      const Vec3 a = pt.y < prev.y ? pt : prev, b = pt.y < prev.y ? prev : pt;
      const double a_yp = pt.y < prev.y ? yp : prev_yp, b_yp = pt.y < prev.y ? prev_yp : yp;
      const double j_lo = std::ceil((a.y - g.y0_mm) / g.dy_mm);
      const double j_hi = std::floor((b.y - g.y0_mm) / g.dy_mm);
      for (double jj = std::max(j_lo, 0.0); jj <= j_hi && jj < static_cast<double>(n); jj += 1.0) {
        const auto j = static_cast<std::size_t>(jj);
        const double u = (g.y(j) - a.y) / (b.y - a.y);
        const double z = a.z + u * (b.z - a.z);
        if (z > z_locus[j]) {
          z_locus[j] = z;
          g.x_locus[j] = a.x + u * (b.x - a.x);
          g.wheel_y[j] = a_yp + u * (b_yp - a_yp);
        }
      }
    }
    prev = pt;
    prev_yp = yp;
    have_prev = true;
  }
}

/// D=5 (spec-additions §A2): at every lateral sample the vertical gap between rail and wheel,
/// z_rail(x, y) − z_wheel(x, y), minimised along x — the gap grid's minimum without the grid:
/// golden sections in a 4 mm window around the locus's x (moved while the minimum lies at its
/// end), then the parabola through the last three points. The wheel's height at (x, y) is where
/// the vertical line meets its lower surface (out-of-round wheels included); this is exact where
/// the locus interpolates between wheel-profile circles, and it does not assume that the wheel's
/// lowest point lies in the view direction.
void minimise_gap_along_x(const PlacedProfiles& prof, const WheelsetPose& pose, GapFunction& g,
                          std::vector<double>& z_locus) {
  for (std::size_t j = 0; j < g.gap.size(); ++j) {
    if (z_locus[j] <= -kNoWheel) continue;
    const double y = g.y(j);
    const double t_start = z_locus[j];
    // gap(x) = rail − wheel at this y; +huge where the vertical line misses either body.
    const auto gap_at = [&](double x) {
      const RailSurfacePoint r = prof.rail_surface_at(x, y);
      double t = 0.0;
      if (!r.found ||
          !wheel_surface_along(prof, pose, Vec3{x, y, 0.0}, Vec3{0.0, 0.0, 1.0}, t_start, t))
        return kNoWheel;
      return r.z - t;
    };
    constexpr double kHalfWindow = 2.0;  // [mm]
    double centre = g.x_locus[j];
    GoldenBracket br;
    for (int shift = 0; shift < 10; ++shift) {
      br = golden_section_minimum(gap_at, centre - kHalfWindow, centre + kHalfWindow, 0.0, 24);
      const double x = 0.5 * (br.a + br.b);
      const bool at_end = std::abs(x - (centre - kHalfWindow)) < 1e-3 ||
                          std::abs(x - (centre + kHalfWindow)) < 1e-3;
      if (!at_end) break;
      centre = x;  // the minimum lies beyond the window: move it
    }
    // The parabola through c, (c+d)/2, d refines the bracket's minimum.
    const double m = 0.5 * (br.c + br.d), fm = gap_at(m), h = 0.5 * (br.d - br.c);
    const double curvature = br.fc - 2.0 * fm + br.fd;
    double x = m;
    if (curvature > 0.0 && h > 0.0) x = m - 0.5 * h * (br.fd - br.fc) / curvature;
    double f = gap_at(x);
    if (!(f <= fm)) {
      x = m;
      f = fm;
    }
    if (!(f < 0.5 * kNoWheel)) continue;
    // The wheel's height there (at z_ws = 0) is the locus point: rail − gap.
    g.x_locus[j] = x;
    z_locus[j] = prof.rail_surface_at(x, y).z - f;
  }
}

ContactRegion make_region(const GapFunction& g, const PlacedProfiles& prof, std::size_t first,
                          std::size_t last, double c, bool linear_weights,
                          const std::vector<SampleMoments>& sliced) {
  ContactRegion r;
  r.first = first;
  r.last = last;
  r.x_min = std::numeric_limits<double>::max();
  r.x_max = -r.x_min;
  r.min_gap = 0.0;
  for (std::size_t j = first; j <= last; ++j) {
    const double pen = -g.gap[j];
    if (!(pen > 0.0)) continue;
    r.min_gap = std::min(r.min_gap, g.gap[j]);
    // A sliced wheel: the integrals over its actual height along x (sliced_weights.hpp); the
    // round wheel's closed form about the locus point otherwise, and for an interpenetration
    // narrower than the integrals' step.
    SampleMoments m;
    if (!sliced.empty() && sliced[j].weight > 0.0) {
      m = sliced[j];
    } else {
      const double t0 = std::sqrt(pen / c);
      m.weight = gap_sample_weight(pen, c, linear_weights);
      m.weight_x = m.weight * g.x_locus[j];
      m.x_min = g.x_locus[j] - t0;
      m.x_max = g.x_locus[j] + t0;
    }
    r.weight += m.weight;
    r.wx += m.weight_x;
    r.wy += m.weight * g.y(j);
    r.wd += m.weight * g.rail_angle[j];
    r.x_min = std::min(r.x_min, m.x_min);
    r.x_max = std::max(r.x_max, m.x_max);
  }
  r.y_min = g.y(first);
  r.y_max = g.y(last);
  const double za = prof.rail_at_track_y(r.y_min).z, zb = prof.rail_at_track_y(r.y_max).z;
  r.z_min = std::min(za, zb);
  r.z_max = std::max(za, zb);
  return r;
}

/// How much lower a roller's or sliced rail's surface lies under the locus at sample j [mm].
double drop_at(const GapSamples& s, std::size_t j) {
  return s.rail_drop.empty() ? 0.0 : s.rail_drop[j];
}

/// A sliced wheel's weight integrals at every interpenetrating sample (its heights along x
/// sampled on first use, every DX/2: XCP on `wheelflat` moves by less than 1e-4 mm from DX/8 to
/// DX).
std::vector<SampleMoments> sliced_sample_moments(const model::WheelRailProblem& p,
                                                 const PlacedProfiles& prof, GapSamples& s,
                                                 const GapFunction& g, double z_ws) {
  std::vector<SampleMoments> out(g.gap.size());
  s.heights_along_x.resize(g.gap.size());
  for (std::size_t j = 0; j < g.gap.size(); ++j) {
    if (!(g.gap[j] < 0.0)) continue;
    HeightsAlongX& h = s.heights_along_x[j];
    const double step = 0.5 * p.search.dx_mm, rail = s.rail_z[j] + drop_at(s, j);
    if (h.empty()) {
      // Over the round wheel's interpenetration 0.3 mm deeper than now: a flat only lifts the
      // wheel, and deeper iterates of the vertical-force iteration rarely go further.
      const double half = std::sqrt((0.3 - g.gap[j]) / rolling_curvature_per_mm(p));
      h = wheel_heights_along_x(prof, s.pose_at_zero, g.y(j), g.x_locus[j], s.locus_z[j], step,
                                half);
    }
    out[j] = gap_moments_along_x(h, rail, z_ws, p.search.linear_gap_weights);
    if (reaches_window_end(h, out[j]) &&
        h.step_mm * static_cast<double>(h.z.size() - 1) < 2.0 * full_window_mm(prof)) {
      // Deeper than the window allowed for: sample the widest one.
      h = wheel_heights_along_x(prof, s.pose_at_zero, g.y(j), g.x_locus[j], s.locus_z[j], step,
                                full_window_mm(prof));
      out[j] = gap_moments_along_x(h, rail, z_ws, p.search.linear_gap_weights);
    }
  }
  return out;
}

/// Reference point and angle from the accumulated weights (physics.md §13.3 step 4).
void finish_region(ContactRegion& r, const PlacedProfiles& prof) {
  const double x = r.wx / r.weight, y = r.wy / r.weight;
  // On the rail's (or the roller's) surface: a roller lies lower at x ≠ 0.
  r.reference = {
      x, y, prof.rail_varies_along_x() ? prof.rail_surface_at(x, y).z : prof.rail_at_track_y(y).z};
  double d = r.wd / r.weight;
  constexpr double kHalfPi = 0.5 * std::numbers::pi;
  if (std::abs(std::abs(d) - kHalfPi) < 1e-3) d = std::copysign(kHalfPi - 1e-3, d);
  r.delta_rad = d;
}

RegionExtent extent_of(const ContactRegion& r) {
  return {r.y_min, r.y_max, r.z_min, r.z_max};
}

double box_distance(const RegionExtent& a, const RegionExtent& b) {
  const double dy = std::max({0.0, b.y_min - a.y_max, a.y_min - b.y_max});
  const double dz = std::max({0.0, b.z_min - a.z_max, a.z_min - b.z_max});
  return std::hypot(dy, dz);
}

/// Interaction factor of two parts at box distance d: 1 up to D_COMB, falling linearly to 0 at
/// D_SEP (docs/decisions.md: the linear ramp reproduces CONTACT's mbench_a22_right case 11).
double interaction_factor(double d, const model::ContactSearchSettings& s) {
  if (d <= s.d_comb_mm) return 1.0;
  if (d >= s.d_sep_mm) return 0.0;
  return (s.d_sep_mm - d) / (s.d_sep_mm - s.d_comb_mm);
}

/// Attenuation factors between the parts of a combined patch; none when all equal 1.
void set_part_factors(ContactRegion& q, const model::ContactSearchSettings& s) {
  const std::size_t n = q.parts.size();
  q.part_factors.assign(n * n, 1.0);
  bool attenuated = false;
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b = 0; b < n; ++b) {
      if (a == b) continue;
      const double f = interaction_factor(box_distance(q.parts[a], q.parts[b]), s);
      q.part_factors[a * n + b] = f;
      attenuated = attenuated || f < 1.0;
    }
  if (!attenuated) {
    q.parts.clear();
    q.part_factors.clear();
  }
}

/// Step 5: neighbouring regions closer than D_SEP (and within A_SEP in angle) form one patch;
/// beyond D_COMB their cross-influence is attenuated (parts with factors).
std::vector<ContactRegion> combine(std::vector<ContactRegion> regions,
                                   const model::ContactSearchSettings& s) {
  std::vector<ContactRegion> out;
  for (ContactRegion& r : regions) {
    if (!out.empty()) {
      ContactRegion& q = out.back();
      const double angle = std::abs(q.wd / q.weight - r.wd / r.weight);
      const double d = box_distance(extent_of(q), extent_of(r));
      if (angle <= s.a_sep_rad && d <= s.d_sep_mm) {
        if (q.parts.empty()) q.parts.push_back(extent_of(q));
        if (d <= s.d_comb_mm) {
          RegionExtent& last = q.parts.back();  // fully combined: one part
          last.y_max = r.y_max;
          last.z_min = std::min(last.z_min, r.z_min);
          last.z_max = std::max(last.z_max, r.z_max);
        } else {
          q.parts.push_back(extent_of(r));
        }
        q.last = r.last;
        q.x_min = std::min(q.x_min, r.x_min);
        q.x_max = std::max(q.x_max, r.x_max);
        q.y_max = r.y_max;
        q.z_min = std::min(q.z_min, r.z_min);
        q.z_max = std::max(q.z_max, r.z_max);
        q.min_gap = std::min(q.min_gap, r.min_gap);
        q.regions += r.regions;
        q.weight += r.weight;
        q.wx += r.wx;
        q.wy += r.wy;
        q.wd += r.wd;
        continue;
      }
    }
    out.push_back(std::move(r));
  }
  for (ContactRegion& q : out)
    if (!q.parts.empty()) set_part_factors(q, s);
  return out;
}

/// Where the gap crosses zero between the interpenetrating sample j and the sample k beyond
/// it, as the fraction of the way from j to k (linear interpolation).
double zero_crossing(const GapFunction& g, std::size_t j, std::size_t k) {
  const double a = g.gap[j], b = g.gap[k];
  if (!(a < 0.0) || !(b >= 0.0) || b >= 0.5 * kNoWheel) return 1.0;
  return a / (a - b);
}

/// The distance between two neighbouring regions along the contact (a below b in y): between
/// their facing zero crossings of the gap, the mean of the rail's and the wheel's arc lengths —
/// the length of the curve midway between the profiles, as D=4's curved reference measures.
double contact_distance(const GapFunction& g, const PlacedProfiles& prof, const ContactRegion& a,
                        const ContactRegion& b) {
  const std::size_t a0 = a.last - 1, a1 = a.last, b0 = b.first + 1, b1 = b.first;
  const double ta = zero_crossing(g, a0, a1), tb = zero_crossing(g, b0, b1);
  const double ya = g.y(a0) + ta * (g.y(a1) - g.y(a0)), yb = g.y(b0) + tb * (g.y(b1) - g.y(b0));
  const double wa = g.wheel_y[a0] + ta * (g.wheel_y[a1] - g.wheel_y[a0]);
  const double wb = g.wheel_y[b0] + tb * (g.wheel_y[b1] - g.wheel_y[b0]);
  const double y_r = prof.rail_y_mm();
  const double rail = std::abs(prof.rail().at_y(yb - y_r).s - prof.rail().at_y(ya - y_r).s);
  const double wheel = std::abs(prof.wheel().at_y(wb).s - prof.wheel().at_y(wa).s);
  return 0.5 * (rail + wheel);
}

/// Step 5 for separate neighbours: between D_SEP and D_TURN (and within A_SEP) their reference
/// angles are turned towards their weight-averaged angle, fully at D_SEP and not at all at
/// D_TURN, linearly in their distance along the contact (contact_distance). On
/// `mbench_a22_varfric` case 3 this gives CONTACT's −0.2480 and −0.2930 rad (unturned −0.1326
/// and −0.2984; the bounding boxes' distance gave −0.2521, the rail's arc alone −0.2482);
/// docs/decisions.md.
void turn_neighbour_angles(std::vector<ContactRegion>& patches,
                           const model::ContactSearchSettings& s, const GapFunction& g,
                           const PlacedProfiles& prof) {
  for (ContactRegion& r : patches) r.delta_own_rad = r.delta_rad;
  if (!(s.d_turn_mm > s.d_sep_mm)) return;
  std::vector<double> turned(patches.size());
  for (std::size_t k = 0; k < patches.size(); ++k) turned[k] = patches[k].delta_rad;
  for (std::size_t k = 0; k + 1 < patches.size(); ++k) {
    ContactRegion& a = patches[k];
    ContactRegion& b = patches[k + 1];
    if (box_distance(extent_of(a), extent_of(b)) <= s.d_sep_mm) continue;  // combined instead
    const double d = contact_distance(g, prof, a, b);
    if (d <= s.d_sep_mm || d > s.d_turn_mm) continue;
    if (std::abs(a.delta_rad - b.delta_rad) > s.a_sep_rad) continue;
    const double f = (s.d_turn_mm - d) / (s.d_turn_mm - s.d_sep_mm);
    const double mean = (a.weight * a.delta_rad + b.weight * b.delta_rad) / (a.weight + b.weight);
    turned[k] += f * (mean - a.delta_rad);
    turned[k + 1] += f * (mean - b.delta_rad);
    a.angle_turned = b.angle_turned = true;
  }
  for (std::size_t k = 0; k < patches.size(); ++k) patches[k].delta_rad = turned[k];
}

}  // namespace

double gap_sample_weight(double pen_mm, double c_per_mm, bool linear) {
  // The gap along x at a sample, g(x) = c·x² − pen, interpenetrates on |x| < t0 = √(pen/c).
  const double t0 = std::sqrt(pen_mm / c_per_mm);
  if (linear) return 2.0 * pen_mm * t0 - (2.0 / 3.0) * c_per_mm * t0 * t0 * t0;  // ∫ −g dx
  return 2.0 * pen_mm * pen_mm * t0 - (4.0 / 3.0) * pen_mm * c_per_mm * t0 * t0 * t0 +
         0.4 * c_per_mm * c_per_mm * std::pow(t0, 5);  // ∫ g² dx
}

double rolling_curvature_per_mm(const model::WheelRailProblem& p) {
  double c = 1.0 / (2.0 * p.wheelset.nominal_radius_mm);
  if (p.roller.enabled) c += 1.0 / (2.0 * p.roller.nominal_radius_mm);
  return c;
}

GapSamples sample_rail(const model::WheelRailProblem& p, const PlacedProfiles& prof) {
  GapSamples s;
  GapFunction& g = s.base;
  // Samples 0.3·DS apart, but at most kMaxGapSamples over the rail profile: a DS of micrometres
  // (the patch grid is coarsened by NPOT_MAX's doubling anyway) asked for gigabytes here.
  const double width = prof.rail().y_max() - prof.rail().y_min();
  g.dy_mm = std::max(0.3 * p.search.ds_mm, width / static_cast<double>(kMaxGapSamples));
  g.y0_mm = prof.rail_y_mm() + prof.rail().y_min();
  const auto n =
      static_cast<std::size_t>((prof.rail().y_max() - prof.rail().y_min()) / g.dy_mm) + 1;
  g.gap.assign(n, kNoWheel);
  g.rail_angle.assign(n, 0.0);
  s.rail_z.assign(n, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t j = 0; j < n; ++j) {
    const CurvePoint r = prof.rail_at_track_y(g.y(j));
    if (!r.found) continue;
    s.rail_z[j] = r.z;
    g.rail_angle[j] = std::atan(r.dz_dy);
  }
  return s;
}

void sample_wheel(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                  const WheelsetPose& pose_at_zero, GapSamples& s) {
  fill_locus(p, prof, pose_at_zero, s);
  s.heights_along_x.clear();
  if (prof.wheel_surface() != nullptr) s.pose_at_zero = pose_at_zero;
  if (p.search.method == model::ContactSearch::GapGrid)
    minimise_gap_along_x(prof, pose_at_zero, s.base, s.locus_z);
  s.rail_drop.clear();
  if (!prof.rail_varies_along_x()) return;
  // The rail's surface under the locus where it differs from its section at x = 0: a roller's
  // circle falls away, a sliced rail changes along the track.
  const GapFunction& g = s.base;
  s.rail_drop.assign(g.gap.size(), 0.0);
  for (std::size_t j = 0; j < g.gap.size(); ++j) {
    if (std::isnan(s.rail_z[j])) continue;
    const RailSurfacePoint r = prof.rail_surface_at(g.x_locus[j], g.y(j));
    s.rail_drop[j] = r.found ? r.z - s.rail_z[j] : kNoWheel;
  }
}

SearchResult search_contact(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                            GapSamples& samples, double z_ws) {
  SearchResult res;
  GapFunction& g = res.gap;
  g = samples.base;
  const std::size_t n = g.gap.size();
  res.min_gap_mm = kNoWheel;
  std::size_t j_min = 0;
  for (std::size_t j = 0; j < n; ++j) {
    if (std::isnan(samples.rail_z[j]) || samples.locus_z[j] <= -kNoWheel) continue;
    g.gap[j] = samples.rail_z[j] + drop_at(samples, j) - (samples.locus_z[j] + z_ws);
    if (g.gap[j] < res.min_gap_mm) {
      res.min_gap_mm = g.gap[j];
      j_min = j;
    }
  }
  res.delta_at_min_rad = g.rail_angle[j_min];
  res.min_gap_between_samples_mm = res.min_gap_mm;
  if (j_min > 0 && j_min + 1 < n && g.gap[j_min - 1] < kNoWheel && g.gap[j_min + 1] < kNoWheel) {
    const double second = g.gap[j_min - 1] - 2.0 * g.gap[j_min] + g.gap[j_min + 1];
    const double slope = g.gap[j_min + 1] - g.gap[j_min - 1];
    res.curvature_at_min = 0.5 * second / (g.dy_mm * g.dy_mm);
    if (second > 0.0) res.min_gap_between_samples_mm -= slope * slope / (8.0 * second);
  }
  res.minimum_at_profile_end = res.min_gap_mm < kNoWheel && (j_min == 0 || j_min + 1 == n);

  // Regions: maximal runs of negative gap, one guard sample on each side.
  const double c = rolling_curvature_per_mm(p);
  const std::vector<SampleMoments> sliced = prof.wheel_surface() != nullptr
                                                ? sliced_sample_moments(p, prof, samples, g, z_ws)
                                                : std::vector<SampleMoments>{};
  std::vector<ContactRegion> regions;
  for (std::size_t j = 0; j < n;) {
    if (!(g.gap[j] < 0.0)) {
      ++j;
      continue;
    }
    std::size_t e = j;
    while (e + 1 < n && g.gap[e + 1] < 0.0) ++e;
    regions.push_back(make_region(g, prof, j > 0 ? j - 1 : j, e + 1 < n ? e + 1 : e, c,
                                  p.search.linear_gap_weights, sliced));
    j = e + 1;
  }
  res.patches = combine(std::move(regions), p.search);
  for (ContactRegion& r : res.patches) finish_region(r, prof);
  turn_neighbour_angles(res.patches, p.search, g, prof);
  if (res.patches.size() > 10) {
    // Keep the ten deepest.
    std::sort(res.patches.begin(), res.patches.end(),
              [](const ContactRegion& a, const ContactRegion& b) { return a.min_gap < b.min_gap; });
    res.patches.resize(10);
  }
  // CONTACT's order: from the field side to the gauge side, i.e. by decreasing lateral position
  // of the (right-wheel) computation (mbench_a22_varfric case 3: the tread patch first).
  std::sort(
      res.patches.begin(), res.patches.end(),
      [](const ContactRegion& a, const ContactRegion& b) { return a.reference.y > b.reference.y; });
  return res;
}

}  // namespace rollcontact::wheelrail
