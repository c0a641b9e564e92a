// Module-1 case writer: see the header. The line order is spec/inp-format.md §5's; the reader
// (inp_module1.cpp) reads it back to the same record for every solve-relevant field.

#include "format/inp/inp_writer_module1.hpp"

#include <fmt/format.h>

#include "format/inp/inp_line_writer.hpp"
#include "format/text/file_names.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

const std::string& CompanionFiles::table_for(const Profile& profile, bool is_wheel) {
  if (const auto it = made_.find(&profile); it != made_.end()) return files_[it->second].name;
  std::string text = fmt::format(
      "% {} profile written by rollcontact: y [mm], z [mm] (positive downwards), read as is\n",
      is_wheel ? "wheel" : "rail");
  for (std::size_t k = 0; k < profile.y.size(); ++k)
    text += fmt::format("{} {}\n", inp_real(profile.y[k]), inp_real(profile.z[k]));
  // Cases that give the same points (each TOML case its own copy) share one table.
  auto [by_text, is_new] = by_text_.try_emplace(text, files_.size());
  if (is_new) {
    CompanionFile f;
    f.name = fmt::format("{}_{}{}.txt", stem_, is_wheel ? "wheel" : "rail",
                         is_wheel ? ++wheels_ : ++rails_);
    f.text = std::move(text);
    files_.push_back(std::move(f));
  }
  made_.emplace(&profile, by_text->second);
  return files_[by_text->second].name;
}

namespace {

/// Writes one module-1 case; "keep" digits never appear (Z=3, E=3 or 5, C, L, G, D explicit).
class WheelRailCaseWriter : InpLineWriter {
 public:
  WheelRailCaseWriter(std::string& out, const WheelRailRecord& r,
                      const std::filesystem::path& base_dir, CompanionFiles& companions)
      : InpLineWriter(out, r.case_number), r_(r), base_dir_(base_dir), companions_(companions) {}

  void write() {
    const ControlDigits& d = r_.digits;
    control_words();
    solver_lines(r_.solver, r_.npot_max);  // lines 5-6
    friction();                            // lines 7-8
    if (r_.materials.influence_type == 4)  // line 9
      group(fmt::format("{} {}", r_.materials.conformal.if_meth, r_.materials.conformal.variant),
            "IF_METH VARIANT");
    material_lines(r_.materials, d.b, d.m);   // line 10
    damping_line(r_.damping);                 // line 11
    if (d.h != 0) heat_lines(r_.heat, d.m);   // line 12
    discretisation();                         // line 13
    track();                                  // lines 14-17
    wheelset();                               // lines 18-22
    if (d.s != 0) subsurface(r_.subsurface);  // line 23
  }

 private:
  bool flexible() const {
    return r_.digits.e == 4 || r_.digits.e == 5 || r_.wheel_deviations.any_above(0.0);
  }

  void control_words() {
    const ControlDigits& d = r_.digits;
    const int s = d.s >= 1 ? 3 : 0;
    const int w1 =
        r_.config * 1000000 + d.p * 100000 + d.b * 10000 + d.t * 1000 + d.n * 100 + d.f * 10 + s;
    const int m2 = r_.damping.enabled ? 2 : 0;
    const int w2 = r_.variable_friction.v * 1000000 + r_.friction.law * 100000 +
                   r_.discretisation.method * 10000 + r_.materials.influence_type * 1000 +
                   d.m * 100 + 3 * 10 + (flexible() ? 5 : 3);
    group(fmt::format("{:07d}", w1), "C-P-B-T-N-F-S");
    group(fmt::format("{:07d} {}", w2, 10 * d.gapwgt + m2), "V-L-D-C-M-Z-E  10*GAPWGT+M2");
    control_word3_and_debug(d, r_.solver.method);
  }

  void friction() {
    const Friction& f = r_.friction;
    const VariableFriction& vf = r_.variable_friction;
    if (vf.v == 1 || vf.v == 2) {
      group(fmt::format("{}", vf.sets.size()), "NVF");
      for (std::size_t k = 0; k < vf.sets.size(); ++k)
        friction_values(f.law, vf.sets[k], vf.v == 1 ? "ALPHA" : "SVF", vf.positions[k]);
    } else {
      friction_values(f.law, FrictionValues{f.fstat, f.fkin, f.params});
    }
    friction_memory(f);
  }

  void discretisation() {
    const WheelRailDiscretisation& s = r_.discretisation;
    group(reals({s.dx, s.ds, s.dqrel, s.a_sep, s.d_sep, s.d_comb, s.d_turn, s.g_miss}),
          "DX DS DQREL A_SEP D_SEP D_COMB D_TURN G_MISS");
  }

  void track() {
    const TrackDimensions& t = r_.track;
    const bool gauge = t.gaught > 0.0;
    group(reals({t.gaught, gauge ? t.gaugsq : t.raily0, gauge ? t.gaugwd : t.railz0,
                 r_.is_roller() ? t.nomradr : t.cant, t.curv}),
          fmt::format("GAUGHT {} {}", gauge ? "GAUGSQ GAUGWD" : "RAILY0 RAILZ0",
                      r_.is_roller() ? "NOMRADR CURV" : "CANT CURV"));
    profile(r_.rail, false);
    const RailDeviations& v = r_.rail_deviations;
    group(reals({v.dy, v.dz, v.droll, v.vy, v.vz, v.vroll}),
          "DYRAIL DZRAIL DROLLR VYRAIL VZRAIL VROLLR");
    if (r_.digits.f == 3) {
      const MasslessRail& m = r_.massless_rail;
      group(reals({m.ky, m.fy, m.kz, m.fz, m.dystep0}), "KYRAIL FYRAIL KZRAIL FZRAIL DYSTEP0");
    }
  }

  void wheelset() {
    const ControlDigits& d = r_.digits;
    const WheelsetDimensions& w = r_.wheelset;
    group(reals({w.fbdist, w.fbpos, w.nomradw, w.ytape}), "FBDIST FBPOS NOMRADW YTAPE");
    profile(r_.wheel, true);
    const WheelsetMotion& m = r_.motion;
    const bool roller = r_.is_roller();
    group(reals({m.s, m.y, d.n == 1 ? m.fz : m.z, m.roll, m.yaw, m.pitch}),
          fmt::format("{} Y_WS {} ROLL YAW PITCH", roller ? "X_WS" : "S_WS",
                      d.n == 1 ? "FZ" : "Z_WS"));
    const double q6 = d.f == 1 ? m.fx : d.f == 2 ? m.my : m.vpitch;
    group(reals({roller ? m.rpitch : m.vs, m.vy, m.vz, m.vroll, m.vyaw, q6}),
          fmt::format("{} VY VZ VROLL VYAW {}", roller ? "RPITCH" : "VS",
                      d.f == 1   ? "FX_WS"
                      : d.f == 2 ? "MY_WS"
                                 : "VPITCH"));
    if (flexible()) {
      const WheelDeviations& v = r_.wheel_deviations;
      group(reals({v.dx, v.dy, v.dz, v.droll, v.dyaw, v.dpitch}),
            "DXWHL DYWHL DZWHL DROLLW DYAWW DPITCHW");
      group(reals({v.vx, v.vy, v.vz, v.vroll, v.vyaw, v.vpitch}),
            "VXWHL VYWHL VZWHL VROLLW VYAWW VPITCHW");
    }
  }

  /// The profile line with every option (PRFOPT = 2). A profile read from a file names that
  /// file; one given as points names its companion table, read as is (the points are already
  /// mirrored and scaled).
  void profile(const ProfileSpec& ps, bool is_wheel) {
    std::string name;
    int mirror_y = ps.mirror_y, mirror_z = ps.mirror_z;
    double scale = ps.scale_yz;
    if (ps.path.empty() && !ps.sliced) {
      name = companions_.table_for(*ps.profile, is_wheel);
      mirror_y = 0;
      mirror_z = -1;
      scale = 1.0;
    } else {
      name = written_input_name(ps.path, base_dir_);
    }
    if (name.find('\'') != std::string::npos || name.size() > 240)
      throw Error(
          fmt::format("case {}: the {} profile name '{}' cannot be written to .inp (quote "
                      "character or longer than 240 characters)",
                      r_.case_number, is_wheel ? "wheel" : "rail", name));
    group(fmt::format("'{}' {} {} {} {} 2", name, mirror_y, inp_real(scale), inp_real(ps.smooth),
                      mirror_z),
          "FNAME MIRRORY SCALEYZ SMOOTH MIRRORZ PRFOPT");
    group(
        fmt::format("{} {}", ps.ismooth, reals({ps.zigthrs, ps.kinkhigh, ps.kinklow, ps.kinkwid})),
        "ISMOOTH ZIGTHRS KINKHIGH KINKLOW KINKWID");
    group(fmt::format("{} {}", ps.errhnd, inp_real(ps.maxomit)), "ERRHND MAXOMIT");
  }

  const WheelRailRecord& r_;
  const std::filesystem::path& base_dir_;
  CompanionFiles& companions_;
};

}  // namespace

void write_wheelrail_case(std::string& out, const WheelRailRecord& r,
                          const std::filesystem::path& base_dir, CompanionFiles& companions) {
  WheelRailCaseWriter(out, r, base_dir, companions).write();
}

}  // namespace rollcontact::format
