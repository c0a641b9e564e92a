#include "format/report/report_wheelrail_inputs.hpp"

#include <fmt/format.h>

#include <ostream>
#include <string>
#include <string_view>

#include "format/report/number_format.hpp"
#include "format/report/report_internal.hpp"

namespace rollcontact::format::report {

namespace {

// Module 1's material constants: g12.4 where it prints fixed (`  0.2800    `), CONTACT's
// significant-digit format where g12.4 would switch to E (`   8.200E+04`, `   1.000E-05`).
std::string g12_or_sig(double v) {
  const std::string g = fortran_g(v, 12, 4);
  return g.find('E') == std::string::npos ? g : fmt_sig(12, 4, 4, v);
}

// The digits say which inputs a case (re)reads: Z=3 the rail profile and the track, Z=1 the
// track only; E=3,5 the wheel profile (spec/inp-format.md §5).
bool reads_rail_profile(const WheelRailRecord& r) {
  return r.digits.z == 3;
}
bool reads_track(const WheelRailRecord& r) {
  return r.digits.z == 1 || r.digits.z == 3;
}
bool reads_wheel_profile(const WheelRailRecord& r) {
  return r.digits.e == 3 || r.digits.e == 5;
}

void write_material(std::ostream& os, const WheelRailRecord& r, const CombinedMaterial& m) {
  const Materials& mat = r.materials;
  const auto& mp = mat.model_params;
  line(os, "");
  line(os, " MATERIAL CONSTANTS");
  line(os, "     NU          G           AK          EPS");
  line(os, "  " + g12_or_sig(m.nu) + g12_or_sig(m.g) + g12_or_sig(m.k) + g12_or_sig(r.solver.eps));
  line(os, "");
  line(os, "    POISS(R)    POISS(W)     GG(R)       GG(W)");
  line(os, "  " + g12_or_sig(mat.poiss1) + g12_or_sig(mat.poiss2) + g12_or_sig(mat.gg1) +
               g12_or_sig(mat.gg2));
  const int model = r.digits.m;
  if (model == 2 || model == 3 || model == 5) {
    // The input's slope-reduction parameters; the factor in effect is the patch's K0_EFF.
    const std::size_t first = model == 2 ? 1 : 0;
    line(os, "");
    line(os, fmt::format(" MODIFIED {} SLOPE REDUCTION PARAMETERS",
                         model == 5 ? "FASTRIP" : "FASTSIM"));
    line(os, "     K0_MF       ALFAMF      BETAMF");
    line(os, "  " + g12(mp[first]) + g12(mp[first + 1]) + g12(mp[first + 2]));
  } else if (model == 4) {
    line(os, "");
    line(os, " INTERFACIAL LAYER PARAMETERS");
    line(os, "     GG3         LAYTHK      TAU_C0      K_TAU");
    line(os, "  " + g12(mp[0]) + g12(mp[1]) + g12(mp[2]) + g12(mp[3]));
  }
}

void write_friction(std::ostream& os, const WheelRailRecord& r) {
  const Friction& fr = r.friction;
  const VariableFriction& vf = r.variable_friction;
  if (vf.v == 0 || vf.sets.empty()) {
    write_friction_block(os, fr, r.digits.o);  // one set, as module 3 prints it
    return;
  }
  line(os, "");
  line(os, " FRICTION LAW PARAMETERS");
  // V=1: one set per rail surface inclination ALPHA [rad]; V=2: per track position SVF [mm].
  line(os, friction_header(fr.law, vf.v == 1 ? "     ALPHA    " : "     SVF      "));
  for (std::size_t i = 0; i < vf.sets.size() && i < vf.positions.size(); ++i) {
    const FrictionValues& set = vf.sets[i];
    line(os,
         "  " + g12(vf.positions[i]) + friction_values(fr.law, set.fstat, set.fkin, set.params));
  }
}

void write_discretisation(std::ostream& os, const WheelRailDiscretisation& ds) {
  line(os, "");
  line(os, " DISCRETISATION PARAMETERS");
  line(os, "     DX          DS          DQREL       A_SEP       D_SEP       D_COMB");
  line(os, "  " + g12(ds.dx) + g12(ds.ds) + g12(ds.dqrel) + g12(ds.a_sep) + g12(ds.d_sep) +
               g12(ds.d_comb));
}

void write_profile(std::ostream& os, const char* body, const ProfileSpec& ps) {
  line(os, "");
  line(os, fmt::format(" {} PROFILE \"{}\"", body, ps.file));
  line(os, "   MIRRORY     MIRRORZ     ISMOOTH      LAMBDA");
  line(os, fortran_i(ps.mirror_y, 7) + fortran_i(ps.mirror_z, 12) + fortran_i(ps.ismooth, 12) +
               fortran_f(ps.smooth, 15, 4));
  line(os, "");
  line(os, "   ZIGTHRS     KINKHIG     KINKLOW      KINKWID     MAXOMIT");
  line(os, "  " + g12(ps.zigthrs) + g12(ps.kinkhigh) + g12(ps.kinklow) + g12(ps.kinkwid) +
               g12(ps.maxomit));
}

void write_track(std::ostream& os, const WheelRailRecord& r) {
  const TrackDimensions& t = r.track;
  // GAUGHT ≤ 0 places the rail's origin at (RAILY0, RAILZ0) instead of at the gauge point;
  // a roller rig has its nominal radius where a track has its cant (docs/decisions.md).
  const bool gauge = t.gaught > 0.0, roller = r.is_roller();
  line(os, "");
  line(os, " TRACK DIMENSIONS AND RAIL POSITION");
  line(os, fmt::format("    {}      {}{}        CURV", gauge ? "GAUGHT" : "RAILY0",
                       gauge ? "GAUGWD" : "RAILZ0", roller ? "     NOMRADR" : "        CANT"));
  line(os, fortran_f(gauge ? t.gaught : t.raily0, 10, 3) +
               fortran_f(gauge ? t.gaugwd : t.railz0, 12, 3) +
               (roller ? fortran_f(t.nomradr, 12, 3) : fortran_f(t.cant, 12, 4)) + sig(t.curv));
}

}  // namespace

void write_profile_reading(std::ostream& os, const WheelRailRecord& r) {
  const auto reading = [&os](const char* body, const ProfileSpec& ps) {
    if (!ps.sliced) {
      line(os, fmt::format(" reading {} profile \"{}\"", body, ps.file));
      return;
    }
    line(os, fmt::format(" Reading file \"{}\" with profile slices", ps.file));
    if (!ps.slices->u.empty())
      line(os, fmt::format(" obtained {} slices, {} = [{},{}]", ps.slices->u.size(),
                           std::string_view(body).starts_with("rail") ? "s" : "th",
                           g12(ps.slices->u.front()), g12(ps.slices->u.back())));
  };
  if (reads_rail_profile(r)) reading("rail ", r.rail);
  if (reads_wheel_profile(r)) reading("wheel", r.wheel);
}

void write_wheelrail_problem_lines(std::ostream& os, const WheelRailRecord& r) {
  const ControlDigits& d = r.digits;
  const char* method = d.b == 5 ? "APPROXIMATE KPEC" : d.b == 6 ? "APPROXIMATE ANALYN" : "FULL";
  line(os, fmt::format(" VERTICAL PROBLEM WITH PRESCRIBED {}, {} SOLUTION",
                       d.n == 1 ? "VERTICAL FORCE" : "POSITION", method));
  if (d.t < 1) return;  // module 1's creepages come from the kinematics
  const char* rolling = d.t == 1   ? " SHIFT TRANSIENT"
                        : d.t == 2 ? " TRANSIENT ROLLING"
                                   : " STEADY STATE ROLLING";
  const char* approach = (d.m == 2 || d.m == 3) ? ", \"FASTSIM APPROACH\""
                         : d.m == 5             ? ", \"FASTRIP APPROACH\""
                                                : "";
  line(os, fmt::format("{}{}, CREEPAGE PRESCRIBED", rolling, approach));
  line(os, frictional_stress_method(r.solver.maxout));
  if (r.materials.influence_type == 4)
    line(os, inclination_correction_method(r.materials.conformal));
}

void write_wheelrail_input_blocks(std::ostream& os, const WheelRailRecord& r,
                                  const CombinedMaterial& material) {
  const ControlDigits& d = r.digits;
  if (d.c >= 2) write_material(os, r, material);
  if (d.l != 1) write_friction(os, r);
  if (d.d >= 2) write_discretisation(os, r.discretisation);
  if (reads_rail_profile(r)) write_profile(os, "RAIL", r.rail);
  if (reads_track(r)) write_track(os, r);
  if (reads_wheel_profile(r)) write_profile(os, "WHEEL", r.wheel);
}

void write_patch_simplified(std::ostream& os, const WheelRailRecord& r, const Solution& s) {
  const int model = r.digits.m;
  if (model != 2 && model != 3 && model != 5) return;
  const SimplifiedReport& simp = s.simplified;
  line(os, "");
  line(os, " SIMPLIFIED THEORY MATERIAL CONSTANTS");
  if (model == 2) {
    line(os, "     FLX");
    line(os, "  " + g12(simp.flx1));
  } else {
    line(os, "     FLX1        FLX2        FLX3");
    line(os, "  " + g12(simp.flx1) + g12(simp.flx2) + g12(simp.flx3));
  }
  line(os, "");
  line(os,
       fmt::format(" MODIFIED {} SLOPE REDUCTION PARAMETERS", model == 5 ? "FASTRIP" : "FASTSIM"));
  line(os, "     K0_EFF");
  line(os, "  " + g12(simp.present ? simp.k_eff : 1.0));
}

}  // namespace rollcontact::format::report
