#include "wheelrail/curved_reference.hpp"

#include <algorithm>
#include <cmath>

#include "rollcontact/errors.hpp"

namespace rollcontact::wheelrail {

namespace {

/// A surface sample: position and unit outward normal (track coordinates).
struct Sample {
  Vec3 point, normal;
};

Vec3 unit(Vec3 v) {
  const double n = std::sqrt(dot(v, v));
  return n > 0.0 ? (1.0 / n) * v : v;
}

/// The rail at arc length s of its placed profile, in the plane x = x_ref: outward normal
/// (0, dz/ds, −dy/ds) (upwards for a rail whose profile runs towards +y). A roller (or a rail
/// varying along the track) is evaluated on its 3-D surface there: a roller's section at x_ref
/// lies lower (higher inside a ring) than its principal profile, its normal tilts along x.
Sample rail_sample(const PlacedProfiles& prof, double s, double x_ref) {
  const CurvePoint c = prof.rail().at_s(s);
  const double y = prof.rail_y_mm() + c.y;
  if (!prof.rail_varies_along_x())
    return {{x_ref, y, prof.rail_z_mm() + c.z}, {0.0, c.dz_ds, -c.dy_ds}};
  const RailSurfacePoint r = prof.rail_surface_at(x_ref, y);
  // ∇(z(x, y) − z) written with the tangent: (z_x·dy/ds, z_y·dy/ds, −dy/ds), z_y·dy/ds the
  // section's dz/ds scaled as the surface's slope is.
  const double scale = c.dz_dy != 0.0 ? r.dz_dy / c.dz_dy : 1.0;
  return {{x_ref, y, r.z}, unit(Vec3{r.dz_dx * c.dy_ds, c.dz_ds * scale, -c.dy_ds})};
}

/// The wheel at arc length s of its profile, on the body of revolution, turned about the axle
/// until it lies in the plane x = x_ref of the track (Newton on the angle from the lowest
/// point). Outward normal: the gradient of ρ − (r0 + z(y)), ρ the distance from the axle.
Sample wheel_sample(const PlacedProfiles& prof, const WheelsetPose& pose, double s, double x_ref) {
  const CurvePoint c = prof.wheel().at_s(s);
  const double r = prof.wheel_r0_mm() + c.z, y = c.y + prof.wheel_y_offset_mm();
  const Mat3& R = pose.wheel_rotation;
  double phi = 0.0;
  for (int it = 0; it < 20; ++it) {
    const double sp = std::sin(phi), cp = std::cos(phi);
    const double f =
        pose.wheel_centre.x + R.r[0][0] * r * sp + R.r[0][1] * y + R.r[0][2] * r * cp - x_ref;
    const double df = R.r[0][0] * r * cp - R.r[0][2] * r * sp;
    if (df == 0.0) break;
    const double step = f / df;
    phi -= step;
    if (std::abs(step) < 1e-13) break;
  }
  const double sp = std::sin(phi), cp = std::cos(phi);
  const Vec3 q{r * sp, y, r * cp};
  // Gradient of ρ − r(y) in the wheel frame: (sin φ, −dz/dy, cos φ), written with the tangent
  // so that a vertical flange (dy/ds = 0) has a finite normal.
  // The wheel profile runs towards −y (canonical order), so (−dy/ds)·∇ points outwards.
  const Vec3 grad{-sp * c.dy_ds, c.dz_ds, -cp * c.dy_ds};
  return {pose.wheel_centre + R * q, unit(R * grad)};
}

}  // namespace

CurvedReference curved_reference(const PlacedProfiles& prof, const WheelsetPose& pose,
                                 const ContactRegion& region, const CurvedRows& rows) {
  const double ds = rows.ds_mm;
  const double y_r = prof.rail_y_mm();
  const double s_ref = prof.rail().at_y(region.reference.y - y_r).s;
  double s_sta = prof.rail().at_y(region.y_min - y_r).s;
  double s_end = prof.rail().at_y(region.y_max - y_r).s;
  if (s_sta > s_end) std::swap(s_sta, s_end);
  s_sta = std::min(s_sta, s_ref);
  s_end = std::max(s_end, s_ref);
  // 20 % slack on either side of the reference, then whole multiples of DS and 3 samples more;
  // the rows counted from the reference, or on a super grid from the rail's origin.
  const double s_pot = rows.on_super_grid ? 0.0 : s_ref;
  const bool cover = rows.cover_lo_mm <= rows.cover_hi_mm;
  double c_sta = s_sta + 0.2 * (s_sta - s_ref) - s_pot;
  double c_end = s_end + 0.2 * (s_end - s_ref) - s_pot;
  if (cover) {
    c_sta = std::min(c_sta, s_ref + rows.cover_lo_mm - s_pot);
    c_end = std::max(c_end, s_ref + rows.cover_hi_mm - s_pot);
  }
  const int k_sta = static_cast<int>(std::floor(c_sta / ds)) - 3;
  const int k_end = static_cast<int>(std::ceil(c_end / ds)) + 3;
  const int n = k_end - k_sta + 1;

  // The wheel's arc length runs against the rail's: s_w = s_w,ref − s̃.
  const Vec3 qw = pose.wheel_rotation.transposed_times(region.reference - pose.wheel_centre);
  const double s_w_ref = prof.wheel().at_y(qw.y - prof.wheel_y_offset_mm()).s;
  const double x_ref = region.reference.x;

  std::vector<Vec3> mid(static_cast<std::size_t>(n)), avg(static_cast<std::size_t>(n));
  int keep_lo = n, keep_hi = -1;
  const int i_ref = static_cast<int>(std::lround((s_ref - s_pot) / ds)) - k_sta;
  for (int i = 0; i < n; ++i) {
    const double sc = ds * (k_sta + i) + s_pot - s_ref;  // from the reference
    const Sample rail = rail_sample(prof, s_ref + sc, x_ref);
    const Sample wheel = wheel_sample(prof, pose, s_w_ref - sc, x_ref);
    const Vec3 m = 0.5 * (rail.point + wheel.point);
    const Vec3 nb = 0.5 * (rail.normal - wheel.normal);
    mid[static_cast<std::size_t>(i)] = {x_ref, m.y, m.z};
    avg[static_cast<std::size_t>(i)] = nb;
    // Inside the region, and rail and wheel not turned away from each other by more than
    // 2·acos(0.9) ≈ 52° (release 25.1).
    if (m.y >= region.y_min && m.y <= region.y_max && std::sqrt(dot(nb, nb)) > 0.9) {
      keep_lo = std::min(keep_lo, i);
      keep_hi = std::max(keep_hi, i);
    }
  }
  if (keep_hi < 0)
    throw GeometryError(
        "conformal contact (D=4): no sample of the curved reference surface lies in the contact "
        "region with rail and wheel facing each other");
  keep_lo = std::min(keep_lo, i_ref - 1);
  keep_hi = std::max(keep_hi, i_ref + 1);
  if (cover) {  // the previous contact's rows, whatever their normals
    keep_lo = std::min(
        keep_lo, static_cast<int>(std::floor((s_ref + rows.cover_lo_mm - s_pot) / ds)) - k_sta);
    keep_hi = std::max(
        keep_hi, static_cast<int>(std::ceil((s_ref + rows.cover_hi_mm - s_pot) / ds)) - k_sta);
  }
  keep_lo = std::max(0, keep_lo - 2);
  keep_hi = std::min(n - 1, keep_hi + 2);

  CurvedReference c;
  c.ds_mm = ds;
  c.k_first = k_sta + keep_lo;
  c.s_origin_mm = s_ref - s_pot;
  for (int i = keep_lo; i <= keep_hi; ++i) {
    const Vec3 nb = avg[static_cast<std::size_t>(i)];
    c.point.push_back(mid[static_cast<std::size_t>(i)]);
    c.normal.push_back(nb);
    c.alpha.push_back(std::atan2(nb.y, -nb.z));
  }
  return c;
}

}  // namespace rollcontact::wheelrail
