#include "wheelrail/conformal_patch.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace rollcontact::wheelrail {

namespace {

/// Per element (ix fastest): the undeformed distance along the row's own normal (before the
/// approach is split off) and the rail and wheel points on the patch normal through it.
struct ElementGeometry {
  std::vector<double> h;
  std::vector<Vec3> rail, wheel;
  std::vector<char> found;
};

/// The planar machinery of D=2 finds rail and wheel on the line through the curved reference's
/// point along the patch normal; the gap along the row's normal ñ_i is that one times
/// cos(α_i − δ) (wheelrail-advanced.md §1.5: locally parallel surfaces, a tilted ruler).
ElementGeometry element_geometry(const PlacedProfiles& prof, const WheelsetPose& pose,
                                 const PatchSetup& s, int mx, int my) {
  const ContactFrame& f = s.frame;
  const CurvedReference& c = *s.curved;
  const std::size_t n = static_cast<std::size_t>(mx) * static_cast<std::size_t>(my);
  ElementGeometry g;
  g.h.assign(n, kFarAway);
  g.rail.resize(n);
  g.wheel.resize(n);
  g.found.assign(n, 0);
  for (int j = 0; j < my; ++j) {
    const std::size_t row = static_cast<std::size_t>(j);
    const Vec3 on_line = f.origin + dot(c.point[row] - f.origin, f.es) * f.es;
    const double cosine = std::cos(c.alpha[row] - f.delta_rad);
    trace_row(prof, pose, f, on_line, mx, s.dx_mm, s.ix0, s.origin_x_mm,
              [&](int i, Vec3 point, double t_rail, double t_wheel) {
                const std::size_t e =
                    row * static_cast<std::size_t>(mx) + static_cast<std::size_t>(i);
                g.h[e] = (t_rail - t_wheel) * cosine;
                g.rail[e] = point + t_rail * f.en;
                g.wheel[e] = point + t_wheel * f.en;
                g.found[e] = 1;
              });
  }
  return g;
}

/// The rail's share f_r of the mid-plane velocity f_r·v_P + (1 − f_r)·v_Q:
/// f_r = (1−ν₁)G₂ / ((1−ν₁)G₂ + (1−ν₂)G₁) (½ for equal bodies).
double rail_share(const model::Bodies& b) {
  const double a = (1.0 - b.body1.poisson_ratio) * b.body2.shear_modulus_N_mm2;
  const double c = (1.0 - b.body2.poisson_ratio) * b.body1.shear_modulus_N_mm2;
  return a + c > 0.0 ? a / (a + c) : 0.5;
}

/// Material velocities of the rail (P) and wheel (Q) points of every element relative to the
/// contact (wheelrail-advanced.md §1.6 step 1): on a track the contact moves with the wheelset
/// at VS, on a roller rig it stays where it is.
struct ElementVelocities {
  std::vector<Vec3> rail, wheel;
};
ElementVelocities element_velocities(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                                     const WheelsetPose& pose, const ElementGeometry& g) {
  const Vec3 frame{p.roller.enabled ? 0.0 : p.motion.vs_mm_s, 0.0, 0.0};
  ElementVelocities v;
  v.rail.resize(g.h.size());
  v.wheel.resize(g.h.size());
  for (std::size_t e = 0; e < g.h.size(); ++e) {
    if (!g.found[e]) continue;
    const Vec3 vp = p.roller.enabled ? roller_point_velocity(p, prof, g.rail[e])
                                     : rail_point_velocity(p, prof, g.rail[e]);
    v.rail[e] = vp - frame;
    v.wheel[e] = wheel_point_motion(p, pose, prof, g.wheel[e]).v - frame;
  }
  return v;
}

/// V and χ (§1.6 step 3): VS on a track; on a roller the mean material speed through the
/// element nearest the reference point; χ = π when the material runs towards +x.
void set_rolling_speed(const model::WheelRailProblem& p, const PatchSetup& s,
                       const ElementGeometry& g, const ElementVelocities& v, int mx, int my,
                       PatchKinematics& k) {
  double speed = p.motion.vs_mm_s;
  if (p.roller.enabled) {
    double best = 1e300;
    speed = 0.0;
    for (int j = 0; j < my; ++j)
      for (int i = 0; i < mx; ++i) {
        const std::size_t e = static_cast<std::size_t>(j) * static_cast<std::size_t>(mx) +
                              static_cast<std::size_t>(i);
        const double x = s.dx_mm * (s.ix0 + i) - s.origin_x_mm;
        const double y = s.curved->s_tilde(static_cast<std::size_t>(j));
        if (!g.found[e] || x * x + y * y >= best) continue;
        best = x * x + y * y;
        speed = -0.5 * (v.rail[e].x + v.wheel[e].x);
      }
  }
  k.veloc_mm_s = std::abs(speed);
  k.chi_rad = speed < 0.0 ? std::numbers::pi : 0.0;
}

/// Rigid slip per element relative to V (§1.6 steps 2–5): the velocities resolved in the row's
/// frame (x, s̃_i, ñ_i); in the (x, ñ) plane each is taken along the mean flow of the two (the
/// mid-plane), so that the wheel's material running down into the contact does not count as
/// longitudinal slip.
std::vector<SlipSample> element_slip(const model::WheelRailProblem& p, const PatchSetup& s,
                                     const ElementGeometry& g, const ElementVelocities& v, int mx,
                                     int my) {
  const PatchKinematics& k = s.kinematics;
  const double sign_chi = std::cos(k.chi_rad) >= 0.0 ? 1.0 : -1.0;
  const double fr = rail_share(p.patch.bodies);
  const double speed = k.veloc_mm_s >= 1e-6 ? k.veloc_mm_s : 1.0;
  const bool shift = p.patch.tangential.kind == model::TangentialKind::Shift;
  const Vec3 ex{1.0, 0.0, 0.0};
  std::vector<SlipSample> w(g.h.size());
  for (int j = 0; j < my; ++j) {
    const std::size_t row = static_cast<std::size_t>(j);
    const Vec3 es = s.curved->tangent(row), en = s.curved->inward_normal(row);
    for (int i = 0; i < mx; ++i) {
      const std::size_t e = row * static_cast<std::size_t>(mx) + static_cast<std::size_t>(i);
      if (!g.found[e]) continue;
      const Vec3 vp = v.rail[e], vq = v.wheel[e];
      if (shift) {  // T=1: the "velocities" are the step's increments, nothing flows
        w[e].wx = dot(vp - vq, ex);
        w[e].wy = dot(vp - vq, es);
        continue;
      }
      const double px = dot(vp, ex), pn = dot(vp, en), qx = dot(vq, ex), qn = dot(vq, en);
      const double mid_x = fr * px + (1.0 - fr) * qx, mid_n = fr * pn + (1.0 - fr) * qn;
      const double len = std::hypot(mid_x, mid_n);
      const double ux = len > 0.0 ? mid_x / len : -sign_chi, un = len > 0.0 ? mid_n / len : 0.0;
      const double along_p = -sign_chi * (px * ux + pn * un);
      const double along_q = -sign_chi * (qx * ux + qn * un);
      w[e].wx = (along_p - along_q) / speed;
      w[e].wy = dot(vp - vq, es) / speed;
    }
  }
  return w;
}

}  // namespace

PatchKinematics fit_average_creepages(const std::vector<SlipSample>& samples) {
  PatchKinematics k;
  if (samples.empty()) return k;
  double xm = 0.0, ym = 0.0, d2 = 0.0, wx = 0.0, wy = 0.0, wz = 0.0;
  for (const SlipSample& q : samples) {
    xm += q.x;
    ym += q.y;
    d2 += q.x * q.x + q.y * q.y;
    wx += q.wx;
    wy += q.wy;
    wz += q.x * q.wy - q.y * q.wx;
  }
  const double n = static_cast<double>(samples.size());
  xm /= n, ym /= n, d2 /= n, wx /= n, wy /= n, wz /= n;
  const double den = d2 - xm * xm - ym * ym;
  if (!(den >= 1e-12)) return k;
  k.phi_per_mm = (wz + ym * wx - xm * wy) / den;
  k.xi = wx + ym * k.phi_per_mm;
  k.eta = wy - xm * k.phi_per_mm;
  return k;
}

void setup_conformal_patch(const model::WheelRailProblem& p, const PlacedProfiles& prof,
                           const WheelsetPose& pose, const ContactRegion& region,
                           const PatchExtent& extent, PatchSetup& s,
                           std::vector<std::string>& warnings) {
  s.frame = contact_frame(region);
  s.dx_mm = p.search.dx_mm;
  s.ds_mm = p.search.ds_mm;
  const bool fixed = on_super_grid(p);
  int mx = 0, my = 0;
  // CONTACT allows 1.2·NPOT_MAX for D=4: the curved reference's 20 % slack.
  const double limit = 1.2 * p.search.max_elements;
  for (int doubling = 0;; ++doubling) {
    CurvedRows rows;
    rows.ds_mm = s.ds_mm;
    rows.on_super_grid = fixed;
    if (s.continued) {
      rows.cover_lo_mm = extent.s_lo_mm;
      rows.cover_hi_mm = extent.s_hi_mm;
    }
    s.curved = curved_reference(prof, pose, region, rows);
    const GridAxis ax =
        cover_axis(extent.x_lo_mm + s.origin_x_mm, extent.x_hi_mm + s.origin_x_mm, s.dx_mm);
    s.ix0 = ax.first;
    s.iy0 = s.curved->k_first;
    s.origin_y_mm = s.curved->s_origin_mm;
    mx = ax.count;
    my = static_cast<int>(s.curved->rows());
    if (static_cast<double>(mx) * my < limit || doubling > 20 || fixed) break;
    s.dx_mm *= 2.0;
    s.ds_mm *= 2.0;
    warnings.push_back(fmt::format(
        "the conformal patch grid would have {} elements, more than 1.2·NPOT_MAX = {:g}: DX, DS "
        "doubled to {:g}, {:g} mm",
        static_cast<long>(mx) * my, limit, s.dx_mm, s.ds_mm));
  }
  model::PatchProblem& q = s.problem;
  q.potential = {};
  q.potential.ipotcn = 1;
  q.potential.mx = mx;
  q.potential.my = my;
  q.potential.values = {(s.ix0 - 0.5) * s.dx_mm - s.origin_x_mm,
                        (s.iy0 - 0.5) * s.ds_mm - s.origin_y_mm, s.dx_mm, s.ds_mm};
  ElementGeometry g = element_geometry(prof, pose, s, mx, my);
  const double h_min = *std::min_element(g.h.begin(), g.h.end());
  s.pen_mm = -h_min;
  q.gap = {};
  q.gap.ibase = 9;
  q.gap.iplan = 1;
  q.gap.values = g.h;
  for (double& v : q.gap.values)
    if (v < kFarAway) v -= h_min;

  // Kinematics (§1.6 step 3); δq as for D=2.
  PatchKinematics& k = s.kinematics;
  k = {};
  k.dq_mm = p.search.dq_rel * p.search.dx_mm;
  const ElementVelocities v = element_velocities(p, prof, pose, g);
  set_rolling_speed(p, s, g, v, mx, my, k);
  const model::TangentialKind kind = p.patch.tangential.kind;
  if (kind == model::TangentialKind::Shift) k = {0.0, 0.0, 0.0, 0.0, 1.0, 1.0};  // as D=2
  if (kind == model::TangentialKind::None) return;
  std::vector<SlipSample> w = element_slip(p, s, g, v, mx, my);
  // Spin arms as the tangential solver takes them: the rolling offset f_φ·δq along χ.
  const double f = kind == model::TangentialKind::Shift ? 0.0 : p.patch.rolling.spin_offset_factor;
  const double off_x = std::cos(k.chi_rad) * k.dq_mm * f, off_y = std::sin(k.chi_rad) * k.dq_mm * f;
  std::vector<SlipSample> inside;
  for (int j = 0; j < my; ++j)
    for (int i = 0; i < mx; ++i) {
      const std::size_t e =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(mx) + static_cast<std::size_t>(i);
      w[e].x = s.dx_mm * (s.ix0 + i) - s.origin_x_mm + off_x;
      w[e].y = s.curved->s_tilde(static_cast<std::size_t>(j)) + off_y;
      if (g.found[e] && g.h[e] < 0.0) inside.push_back(w[e]);
    }
  const PatchKinematics fit = fit_average_creepages(inside);
  k.xi = fit.xi;
  k.eta = fit.eta;
  k.phi_per_mm = fit.phi_per_mm;
  // The remainder stays with the elements, so the total rigid slip is the one computed.
  std::vector<double>& extra = q.tangential.extra_slip;
  extra.assign(2 * w.size(), 0.0);
  for (std::size_t e = 0; e < w.size(); ++e) {
    if (!g.found[e]) continue;
    extra[2 * e] = w[e].wx - (k.xi - k.phi_per_mm * w[e].y);
    extra[2 * e + 1] = w[e].wy - (k.eta + k.phi_per_mm * w[e].x);
  }
}

ConformalPatch conformal_forces(const PatchSetup& s, const Solution& sol) {
  const CurvedReference& c = *s.curved;
  const ContactFrame& f = s.frame;
  ConformalPatch out;
  out.active = true;
  out.ds_mm = c.ds_mm;
  out.row0_s_mm = c.s_tilde(0);
  for (std::size_t i = 0; i < c.rows(); ++i) {
    out.row_y_mm.push_back(c.point[i].y);
    out.row_z_mm.push_back(c.point[i].z);
    out.row_alpha_rad.push_back(c.alpha[i]);
  }
  if (sol.pn.empty()) return out;
  const bool tangential = !sol.px.empty() && !sol.py.empty();
  const double area = sol.grid.dx * sol.grid.dy;
  Vec3 m{};
  for (int iy = 0; iy < sol.grid.my; ++iy) {
    const std::size_t row = static_cast<std::size_t>(iy);
    const double d = c.alpha[row] - f.delta_rad, cd = std::cos(d), sd = std::sin(d);
    // The row's point in the planar frame: the curved grid extruded along x.
    const double s_p = dot(c.point[row] - f.origin, f.es), n_p = dot(c.point[row] - f.origin, f.en);
    for (int ix = 0; ix < sol.grid.mx; ++ix) {
      const std::size_t e = sol.grid.index(ix, iy);
      const double pn = sol.pn[e];
      if (pn <= 0.0) continue;
      const double px = tangential ? sol.px[e] : 0.0, ps = tangential ? sol.py[e] : 0.0;
      const double x = sol.grid.x_centre(ix);
      out.tilde_fn += pn;
      out.tilde_fx += px;
      out.tilde_fs += ps;
      const double bx = px, bs = ps * cd - pn * sd, bn = ps * sd + pn * cd;
      out.bar_fx += bx;
      out.bar_fs += bs;
      out.bar_fn += bn;
      m = m + Vec3{s_p * bn - n_p * bs, n_p * bx - x * bn, x * bs - s_p * bx};
      if (out.contact_row_first < 0) out.contact_row_first = iy;
      out.contact_row_last = iy;
    }
  }
  out.tilde_fn *= area, out.tilde_fx *= area, out.tilde_fs *= area;
  out.bar_fn *= area, out.bar_fx *= area, out.bar_fs *= area;
  out.moment_planar = {m.x * area, m.y * area, m.z * area};
  return out;
}

}  // namespace rollcontact::wheelrail
