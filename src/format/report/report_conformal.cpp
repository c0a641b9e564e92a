#include "format/report/report_conformal.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>
#include <string>

#include "format/report/number_format.hpp"
#include "format/report/report_internal.hpp"

namespace rollcontact::format::report {

namespace {

double degrees(double rad) {
  return rad * 180.0 / std::numbers::pi;
}

}  // namespace

void write_conformal_diagnostics(std::ostream& os, const WheelRailPatch& w) {
  const ConformalPatch& c = w.conformal;
  const int my = static_cast<int>(c.row_alpha_rad.size());
  line(os, "");
  if (c.contact_row_first >= 0) {
    const int i0 = c.contact_row_first, i1 = c.contact_row_last;
    const double s0 = c.row0_s_mm + c.ds_mm * (i0 - 0.5), s1 = c.row0_s_mm + c.ds_mm * (i1 + 0.5);
    line(os, fmt::format(" Actual contact on columns iy = [{:3d},{:3d}] (my={:3d}), sc = [{:7.3f},"
                         "{:7.3f}]",
                         i0 + 1, i1 + 1, my, s0, s1));
    const double a0 = degrees(c.row_alpha_rad[static_cast<std::size_t>(i0)]);
    const double a1 = degrees(c.row_alpha_rad[static_cast<std::size_t>(i1)]);
    line(os, fmt::format(" Reference contact angle delttr = {:6.2f} deg, range = [{:7.2f},{:7.2f}] "
                         "deg",
                         degrees(w.contact_angle_rad), std::min(a0, a1), std::max(a0, a1)));
  } else {
    line(os, fmt::format(" No contact on the {} rows of the curved reference", my));
  }
  line(os, fmt::format(" Total moments Mxp = {:11.1f}, Msp = {:11.1f}, Mnp = {:11.1f} N.mm",
                       c.moment_planar.x, c.moment_planar.y, c.moment_planar.z));
}

void write_row_friction(std::ostream& os, const ConformalPatch& c) {
  line(os, "");
  line(os, " FRICTION LAW PARAMETERS");
  line(os, "      IY         FSTAT       FKIN");
  const std::size_t n = c.row_friction.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (n > 5 && i == 2) {
      line(os, "                      ...");
      i = n - 3;
      continue;
    }
    line(os, fmt::format("{:10d}", i + 1) + sig(c.row_friction[i]) + sig(c.row_friction[i]));
  }
}

void write_conformal_forces(std::ostream& os, const WheelRailPatch& w, double mu_scale, double eps,
                            bool with_temperature) {
  const ConformalPatch& c = w.conformal;
  const Totals& t = w.solution.totals;
  const double noise = 0.5 * eps * c.tilde_fn * mu_scale;
  line(os, "");
  line(os, " TOTAL FORCES, TORSIONAL MOMENT, ELASTIC ENERGY, FRICTIONAL POWER");
  line(os, "     BAR_FN      BAR_FX      BAR_FS      MN         ELAST.EN.   FRIC.POWER");
  line(os, "  " + sig(c.bar_fn) + sig(filter_small(c.bar_fx, noise)) +
               sig(filter_small(c.bar_fs, noise)) + sig(filter_small(c.moment_planar.z, noise)) +
               sig(t.elastic_energy) + sig(t.frictional_power));
  const bool unscaled = mu_scale == 1.0;
  line(os, std::string(unscaled ? "     TILDE_FN    FX/FN       FS/FN    "
                                : "     TILDE_FN  FX/FSTAT/FN FS/FSTAT/FN") +
               "   APPROACH     PMAX    " + (with_temperature ? "  MAX(T1,T2)" : ""));
  const double scale = c.tilde_fn * mu_scale;
  line(os, "  " + sig(c.tilde_fn) +
               sig(filter_small(scale != 0 ? c.tilde_fx / scale : 0.0, 0.5 * eps)) +
               sig(filter_small(scale != 0 ? c.tilde_fs / scale : 0.0, 0.5 * eps)) +
               fmt_sig(12, 6, 4, t.pen) + sig(t.pmax) +
               (with_temperature ? sig(std::max(t.max_temp1, t.max_temp2)) : ""));
}

void write_curved_reference(std::ostream& os, const ConformalPatch& c) {
  line(os, "");
  line(os, fmt::format(" CURVED REFERENCE SURFACE, TRACK COORDINATES,{:5d} POINTS:",
                       c.row_y_mm.size()));
  line(os, "    I        Y(I)       Z(I)       A(I)");
  for (std::size_t i = 0; i < c.row_y_mm.size(); ++i)
    line(os, fmt::format("{:6d}{:11.4f}{:11.4f}{:11.4f}", i + 1, c.row_y_mm[i], c.row_z_mm[i],
                         c.row_alpha_rad[i]));
}

}  // namespace rollcontact::format::report
