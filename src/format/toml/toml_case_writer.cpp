#include "format/toml/toml_case_writer.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <string_view>
#include <variant>

#include "format/inp/to_wheelrail.hpp"
#include "format/text/atomic_file.hpp"
#include "format/text/file_names.hpp"
#include "format/toml/toml_case_schema.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

namespace schema = toml_schema;

/// Shortest text that parses back to exactly `v`, always recognisable as a TOML float.
std::string real(double v) {
  std::string s = fmt::format("{}", v);
  if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // "200" would be an integer
  return s;
}

std::string quote(std::string_view text) {
  std::string s = "\"";
  for (const char ch : text) {
    switch (ch) {
      case '"':
        s += "\\\"";
        break;
      case '\\':
        s += "\\\\";
        break;
      case '\n':
        s += "\\n";
        break;
      case '\t':
        s += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(ch) < 0x20) {
          s += fmt::format("\\u{:04X}", static_cast<unsigned>(ch));
        } else {
          s += ch;
        }
    }
  }
  return s + "\"";
}

/// Name of `code` in `choices`; a value without a name cannot be expressed in a case file.
std::string named(std::span<const schema::Choice> choices, int code, std::string_view what,
                  const CaseRecord& p) {
  const std::string_view n = schema::name_of(choices, code);
  if (n.empty()) {
    throw Error(fmt::format("case {}: {} = {} has no TOML case-file equivalent", p.case_number,
                            what, code));
  }
  return quote(n);
}

/// An array of reals; long arrays wrap six values per line so files stay readable.
std::string real_array(std::span<const double> v) {
  std::string s = "[";
  const bool wrap = v.size() > 6;
  for (std::size_t k = 0; k < v.size(); ++k) {
    if (wrap && k % 6 == 0) s += "\n  ";
    s += real(v[k]);
    if (k + 1 < v.size()) s += wrap && k % 6 == 5 ? "," : ", ";
  }
  return s + (wrap ? ",\n]" : "]");
}

std::string int_array(std::span<const int> v) {
  std::string s = "[";
  for (std::size_t k = 0; k < v.size(); ++k) s += fmt::format("{}{}", k ? ", " : "", v[k]);
  return s + "]";
}

std::string pair(double a, double b) {
  return fmt::format("[{}, {}]", real(a), real(b));
}

/// Writes one case; `out` receives TOML text.
/// The law values of one friction set as `key = value` pairs separated by `sep`.
std::string law_values(int law, const FrictionValues& v, std::string_view sep) {
  const std::array<double, 4>& q = v.params;
  if (law == 0) return fmt::format("static = {}{}kinetic = {}", real(v.fstat), sep, real(v.fkin));
  if (law == 6) {
    return fmt::format(
        "reference = {1}{0}reference_temperature_C = {2}{0}change = {3}{0}temperature_span_C = "
        "{4}",
        sep, real(v.fkin), real(q[0]), real(q[1]), real(q[2]));
  }
  return fmt::format("kinetic = {1}{0}excess = {2}{0}decay_speed_mm_per_s = {3}", sep, real(v.fkin),
                     pair(q[0], q[2]), pair(q[1], q[3]));
}

class CaseWriter {
 public:
  CaseWriter(std::string& out, const CaseRecord& p, const std::filesystem::path& base_dir)
      : out_(out), p_(p), base_dir_(base_dir) {}

  void write() {
    header();
    normal();
    tangential();
    friction();
    material();
    grid();
    geometry();
    solver();
    output();
    damping();
    heat();
    subsurface();
  }

  /// The sections a wheel/rail case shares with module 3 (its patch settings).
  /// The tables module 3 and wheel/rail cases share; `with_friction` false: the caller writes
  /// [case.friction] itself (a wheel/rail case's friction varying along the rail).
  void write_shared(bool with_friction = true) {
    if (with_friction) friction();
    material();
    solver();
    output();
    damping();
    heat();
    subsurface();
  }

 private:
  void line(std::string_view key, const std::string& value) {
    out_ += fmt::format("{} = {}\n", key, value);
  }
  void table(std::string_view name) { out_ += fmt::format("\n[case.{}]\n", name); }

  void header() {
    const ControlDigits& d = p_.digits;
    out_ += "\n[[case]]\n";
    if (!p_.source.file.empty()) {
      out_ += fmt::format("# from {} line {} (case {})\n", p_.source.file, p_.source.first_line,
                          p_.case_number);
    }
    if (p_.result_element != 0) line("result_element", fmt::format("{}", p_.result_element));
    if (p_.contact_problem != 1) line("contact_problem", fmt::format("{}", p_.contact_problem));
    if (d.r == 2 || d.r == 3) line("solve", "false");
    line("previous_state", named(schema::previous_state, d.p, "P", p_));
    if (d.i != 0) line("initial_estimate", named(schema::initial_estimate, d.i, "I", p_));
    if (d.gapwgt != 0) line("gap_weighting", named(schema::gap_weighting, d.gapwgt, "GAPWGT", p_));
  }

  void normal() {
    const ControlDigits& d = p_.digits;
    table("normal");
    line("method", named(schema::normal_method, d.b, "B", p_));
    if (d.n == 1) {
      line("force_N", real(p_.kinematics.fn));
    } else {
      line("approach_mm", real(p_.kinematics.pen));
    }
    if (d.b == 1) line("layer_flexibility_mm3_per_N", real(p_.materials.flxz));
  }

  void tangential() {
    const ControlDigits& d = p_.digits;
    const Kinematics& k = p_.kinematics;
    const int e = k.extra_slip_mode;
    const bool trivial = d.t == 0 && d.f == 0 && k.cksi == 0.0 && k.ceta == 0.0 && k.cphi == 0.0 &&
                         k.spinxo == 0.0 && k.spinyo == 0.0 && e == 0;
    if (trivial) return;
    const bool shift = d.t == 1;
    table("tangential");
    line("problem", named(schema::tangential_problem, d.t, "T", p_));
    if (d.f >= 1) {
      line("force_x_rel", real(k.fx_rel));
    } else {
      line(shift ? "shift_x_mm" : "creepage_x", real(k.cksi));
    }
    if (d.f == 2) {
      line("force_y_rel", real(k.fy_rel));
    } else {
      line(shift ? "shift_y_mm" : "creepage_y", real(k.ceta));
    }
    line(shift ? "rotation_rad" : "spin_rad_per_mm", real(k.cphi));
    if (k.spinxo != 0.0 || k.spinyo != 0.0) line("spin_centre_mm", pair(k.spinxo, k.spinyo));
    if (e != 0) line("extra_slip", named(schema::extra_slip, e, "E", p_));
    if (e == 9) line("extra_slip_per_element", real_array(k.extra_slip));
    if (d.t >= 2) {
      table("tangential.rolling");
      line("direction_rad", real(k.chi));
      line("step_mm", real(k.dq));
      line("velocity_mm_per_s", real(k.veloc));
      line("spin_offset_factor", real(k.facphi));
    }
  }

  void friction() {
    const Friction& f = p_.friction;
    table("friction");
    line("law", named(schema::friction_law, f.law, "L", p_));
    if (p_.digits.v == 3) {
      out_ += "rows = [  # one per grid row iy = 1..MY\n";
      for (const FrictionValues& r : f.rows)
        out_ += fmt::format("  {{ {} }},\n", law_values(f.law, r, ", "));
      out_ += "]\n";
    } else if (p_.digits.v == 0) {
      out_ += law_values(f.law, {f.fstat, f.fkin, f.params}, "\n") + "\n";
    } else {
      throw Error(fmt::format("case {}: variable friction V={} has no TOML case-file equivalent",
                              p_.case_number, p_.digits.v));
    }
    if (f.law == 2 || f.law == 3 || f.law == 4 || f.law == 6) {
      line("memory_distance_mm", real(f.memdst));
      line("memory_speed_mm_per_s", real(f.mem_s0));
    }
  }

  void material() {
    const Materials& m = p_.materials;
    const int model = p_.digits.m;
    const auto& q = m.model_params;
    table("material");
    line("body1",
         fmt::format("{{ poisson = {}, shear_modulus_MPa = {} }}", real(m.poiss1), real(m.gg1)));
    line("body2",
         fmt::format("{{ poisson = {}, shear_modulus_MPa = {} }}", real(m.poiss2), real(m.gg2)));
    line("model", named(schema::material_model, model, "M", p_));
    line("influence", named(schema::influence, m.influence_type, "C", p_));
    if (m.influence_type == 9) {
      line("influence_file", quote(written_input_name(m.influence_file, base_dir_)));
    }
    if (model == 1) {
      line("viscoelastic", fmt::format("{{ modulus_factor = {}, relaxation_time_s = {} }}",
                                       pair(q[0], q[1]), pair(q[2], q[3])));
    }
    if (model == 2) line("flexibility_mm3_per_N", real(q[0]));
    if (model == 2 || model == 3 || model == 5) {
      const std::size_t o = model == 2 ? 1 : 0;
      line("slope_reduction", fmt::format("{{ k0 = {}, alpha = {}, beta = {} }}", real(q[o]),
                                          real(q[o + 1]), real(q[o + 2])));
    }
    if (model == 4) {
      line("interfacial_layer",
           fmt::format("{{ shear_modulus_MPa = {}, thickness_mm = {}, yield_stress_MPa = {}, "
                       "hardening_N_per_mm3 = {} }}",
                       real(q[0]), real(q[1]), real(q[2]), real(q[3])));
    }
    if (m.influence_type == 4) {
      table("material.conformal");
      line("method", fmt::format("{}", m.conformal.if_meth));
      line("variant", fmt::format("{}", m.conformal.variant));
      if (!m.conformal.y.empty()) {  // module 1 computes its own
        line("y_mm", real_array(m.conformal.y));
        line("inclination_rad", real_array(m.conformal.alpha));
      }
    }
  }

  void grid() {
    const PotentialContact& pc = pc_();
    const auto& v = pc.values;
    const std::string elements = fmt::format("elements = [{}, {}]", pc.mx, pc.my);
    table("grid");
    switch (pc.ipotcn) {
      case 1:
        line("rectangle", fmt::format("{{ {}, lower_left_mm = {}, element_size_mm = {} }}",
                                      elements, pair(v[0], v[1]), pair(v[2], v[3])));
        break;
      case 2:
        line("rectangle", fmt::format("{{ {}, lower_left_mm = {}, upper_right_mm = {} }}", elements,
                                      pair(v[0], v[1]), pair(v[2], v[3])));
        break;
      case 3:
        line("rectangle", fmt::format("{{ {}, first_centre_mm = {}, element_size_mm = {} }}",
                                      elements, pair(v[0], v[1]), pair(v[2], v[3])));
        break;
      case 4:
        line("rectangle", fmt::format("{{ {}, first_centre_mm = {}, last_centre_mm = {} }}",
                                      elements, pair(v[0], v[1]), pair(v[2], v[3])));
        break;
      case -1:
        line("hertz", fmt::format("{{ {}, curvatures_per_mm = {}, scale = {} }}", elements,
                                  pair(v[0], v[1]), real(v[2])));
        break;
      case -2:
        line("hertz",
             fmt::format("{{ {}, curvature_x_per_mm = {}, semi_axis_ratio = {}, scale = {} }}",
                         elements, real(v[0]), real(v[1]), real(v[2])));
        break;
      case -3:
        line("hertz", fmt::format("{{ {}, semi_axes_mm = {}, scale = {} }}", elements,
                                  pair(v[0], v[1]), real(v[2])));
        break;
      case -4:
        line("hertz_2d",
             fmt::format("{{ {}, curvature_x_per_mm = {}, half_width_mm = {}, scale = {} }}",
                         elements, real(v[0]), real(v[1]), real(v[2])));
        break;
      case -5:
        line("hertz_2d",
             fmt::format("{{ {}, half_length_mm = {}, half_width_mm = {}, scale = {} }}", elements,
                         real(v[0]), real(v[1]), real(v[2])));
        break;
      case -6:
        line("sdec", fmt::format("{{ {}, semi_axis_x_mm = {}, half_width_mm = {}, scale = {} }}",
                                 elements, real(v[0]), pair(v[1], v[2]), real(v[3])));
        break;
      default:
        throw Error(fmt::format("case {}: IPOTCN = {} has no TOML case-file equivalent",
                                p_.case_number, pc.ipotcn));
    }
  }

  void geometry() {
    if (pc_().ipotcn < 0) return;
    const UndeformedDistance& g = p_.geometry;
    table("geometry");
    switch (g.ibase) {
      case 1:
        out_ += "# h = b1 x² + b2 xy + b3 y² + b4 x + b5 y + b6  [mm]\n";
        line("quadratic", real_array(g.coeffs));
        break;
      case 3:
        out_ += "# h = b1 sin(b2 (x - b3)) - b4 sin(b5 (x - b6)) + x²/b7 + y²/b8  [mm]\n";
        line("sines", real_array(g.coeffs));
        break;
      case 9:
        out_ += "# h per element [mm], ix fastest\n";
        line("per_element_mm", real_array(g.values));
        break;
      case 2:
        table("geometry.profile");
        line("y_first_mm", real(g.y1));
        line("y_step_mm", real(g.dy1));
        line("x_centre_mm", real(g.xm));
        line("x_radius_mm", real(g.rm));
        line("heights_mm", real_array(g.coeffs));
        break;
      default:
        throw Error(fmt::format("case {}: IBASE = {} has no TOML case-file equivalent",
                                p_.case_number, g.ibase));
    }
    if (g.iplan == 1) return;
    table("geometry.planform");
    auto rectangles = [&](std::size_t n) {
      std::string s = "[";
      for (std::size_t r = 0; r < n; ++r) {
        const std::span<const double> rect(g.planform.data() + 4 * r, 4);
        s += fmt::format("{}\n  {}", r ? "," : "", real_array(rect));
      }
      return s + ",\n]";
    };
    if (g.iplan == 2) {
      line("quadratic", real_array(g.planform));
    } else if (g.iplan == 3) {
      out_ += "# [xl, xh, yl, yh] per rectangle [mm]\n";
      line("two_rectangles", rectangles(2));
    } else {
      out_ += "# [xl, xh, yl, yh] per patch [mm]\n";
      line("patches", rectangles(static_cast<std::size_t>(g.npatch)));
      if (!g.patch_factors.empty()) line("factors", real_array(g.patch_factors));
    }
  }

  void solver() {
    const SolverSettings& s = p_.solver;
    table("solver");
    line("method", named(schema::solver_method, s.method, "G", p_));
    line("max_inner_iterations", fmt::format("{}", s.maxgs));
    line("max_outer_iterations", fmt::format("{}", s.maxin));
    line("max_newton_iterations", fmt::format("{}", s.maxnr));
    line("max_coupling_iterations", fmt::format("{}", s.maxout));
    line("tolerance", real(s.eps));
    if (s.method == 2 || s.method == 3) {
      line("omega_normal", real(s.omega_h));
      line("omega_tangential", real(s.omega_s));
    }
    if (s.method >= 2 && s.method <= 4) {
      line("initial_slip", fmt::format("{}", s.inislp));
      line("slip_relaxation", real(s.omgslp));
    }
    if (s.method == 5) {
      const auto& gd = s.gd;
      line("gd_steady",
           fmt::format("{{ fdecay = {}, betath = {}, kdowfb = {}, d_ifc = {}, d_lin = "
                       "{}, d_cns = {}, d_slp = {}, pow_s = {} }}",
                       real(gd.fdecay), real(gd.betath), gd.kdowfb, real(gd.d_ifc), real(gd.d_lin),
                       real(gd.d_cns), real(gd.d_slp), real(gd.pow_s)));
    }
  }

  void output() {
    const ControlDigits& d = p_.digits;
    table("output");
    line("report_level", fmt::format("{}", d.o));
    line("mat_file", named(schema::mat_file, d.a, "A", p_));
    if (d.w != 0) line("trace_level", fmt::format("{}", d.w));
    if (d.x == 1) {
      const DebugDigits& g = d.debug;
      table("debug");
      line("profiles", fmt::format("{}", g.p));
      line("smoothing", fmt::format("{}", g.s));
      line("force_loop", fmt::format("{}", g.f));
      line("contact_search", fmt::format("{}", g.l));
      line("patches", fmt::format("{}", g.c));
      line("influence", fmt::format("{}", g.i));
      line("solver", fmt::format("{}", g.n));
      line("input_echo", fmt::format("{}", g.readln));
    }
  }

  void damping() {
    const Damping& dm = p_.damping;
    if (!dm.enabled) return;
    table("damping");
    line("normal_time_s", real(dm.cdampn));
    line("tangential_time_s", real(dm.cdampt));
    line("max_normal_force_rate_N_per_s", real(dm.dfnmax));
    line("max_tangential_force_rate_N_per_s", real(dm.dftmax));
  }

  void heat() {
    if (p_.digits.h == 0) return;
    const HeatParameters& h = p_.heat;
    auto body = [](double t, double cp, double lambda, double dens) {
      return fmt::format(
          "{{ temperature_C = {}, heat_capacity_J_per_kg_C = {}, "
          "conductivity_W_per_mm_C = {}, density_kg_per_mm3 = {} }}",
          real(t), real(cp), real(lambda), real(dens));
    };
    table("heat");
    line("body1", body(h.bktemp1, h.heatcp1, h.lambda1, h.dens1));
    line("body2", body(h.bktemp2, h.heatcp2, h.lambda2, h.dens2));
    if (p_.digits.m == 4) line("plastic_heat_fraction", real(h.betapl));
  }

  void subsurface() {
    if (p_.digits.s == 0) return;
    const Subsurface& s = p_.subsurface;
    table("subsurface");
    line("mat_file", named(schema::subsurface_file, s.matfil, "MATFIL_S", p_));
    line("report", fmt::format("{}", s.output));
    for (const SubsurfaceBlock& b : s.blocks) {
      out_ += "\n[[case.subsurface.block]]\n";
      switch (b.isubs) {
        case 2:
        case 6:
          line("columns", fmt::format("[{}, {}, {}]  # first, step, last", b.ixl, b.ixinc, b.ixh));
          line("rows", fmt::format("[{}, {}, {}]", b.iyl, b.iyinc, b.iyh));
          break;
        case 3:
        case 7:
          line("column_list", int_array(b.ix));
          line("row_list", int_array(b.iy));
          break;
        case 9:
          line("x_mm", real_array(b.x));
          line("y_mm", real_array(b.y));
          break;
        default:
          break;  // 1, 5: all elements
      }
      if (b.isubs == 1 || b.isubs == 2 || b.isubs == 3) {
        line("z_first_mm", real(b.zl));
        line("z_step_mm", real(b.dz));
        line("z_count", fmt::format("{}", b.z.size()));
      } else {
        line("z_mm", real_array(b.z));
      }
    }
  }

  const PotentialContact& pc_() const { return p_.potential; }

  std::string& out_;
  const CaseRecord& p_;
  const std::filesystem::path& base_dir_;
};

/// Writes one wheel/rail case ([case.wheel_rail], docs/case-files.md).
class WheelRailWriter {
 public:
  WheelRailWriter(std::string& out, const WheelRailRecord& r, const std::filesystem::path& base_dir)
      : out_(out), r_(r), base_dir_(base_dir) {}

  void write() {
    const ControlDigits& d = r_.digits;
    out_ += "\n[[case]]\n";
    if (!r_.source.file.empty())
      out_ += fmt::format("# from {} line {} (case {}, module 1)\n", r_.source.file,
                          r_.source.first_line, r_.case_number);
    if (r_.result_element != 0) line("result_element", fmt::format("{}", r_.result_element));
    if (d.r == 2 || d.r == 3) line("solve", "false");
    // A sequence continues from the previous case as the .inp said (P, I).
    if (d.p != 2) line("previous_state", named(schema::previous_state, d.p, "P", id_));
    if (d.i != 0) line("initial_estimate", named(schema::initial_estimate, d.i, "I", id_));
    table("case.tangential");
    line("problem", named(schema::tangential_problem, d.t, "T", id_));
    if (d.b != 0) {
      table("case.normal");
      line("method", named(schema::normal_method, d.b, "B", id_));
      if (d.b == 1) line("layer_flexibility_mm3_per_N", real(r_.materials.flxz));
    }
    const bool varying_friction = r_.variable_friction.v != 0;
    if (varying_friction) friction_along_rail();
    CaseWriter(out_, id_, base_dir_).write_shared(!varying_friction);
    wheel_rail();
  }

 private:
  void line(std::string_view key, const std::string& value) {
    out_ += fmt::format("{} = {}\n", key, value);
  }
  void table(std::string_view name) { out_ += fmt::format("\n[{}]\n", name); }

  /// [case.friction] with V=1, 2: one set of law values per control point.
  void friction_along_rail() {
    const Friction& f = r_.friction;
    const VariableFriction& vf = r_.variable_friction;
    table("case.friction");
    line("law", named(schema::friction_law, f.law, "L", id_));
    line("along", vf.v == 1 ? "\"inclination\"  # ALPHA [rad]" : "\"track\"  # SVF [mm]");
    out_ += "points = [\n";
    for (std::size_t k = 0; k < vf.sets.size(); ++k) {
      const FrictionValues& s = vf.sets[k];
      out_ +=
          fmt::format("  {{ at = {}, {} }},\n", real(vf.positions[k]), law_values(f.law, s, ", "));
    }
    out_ += "]\n";
    if (f.law == 2 || f.law == 3 || f.law == 4 || f.law == 6) {
      line("memory_distance_mm", real(f.memdst));
      line("memory_speed_mm_per_s", real(f.mem_s0));
    }
  }

  void profile(std::string_view key, const ProfileSpec& ps) {
    table(fmt::format("case.wheel_rail.{}", key));
    if (ps.path.empty() && !ps.sliced) {
      // Given as points: written as read, already mirrored and scaled (z downwards).
      line("points", fmt::format("{{ y_mm = {}, z_mm = {} }}", real_array(ps.profile->y),
                                 real_array(ps.profile->z)));
      line("mirror_z", "\"no\"");
    } else {
      line("file", quote(written_input_name(ps.path, base_dir_)));
      if (ps.mirror_y == 1) line("mirror_y", "true");
      if (ps.mirror_z != 0) line("mirror_z", ps.mirror_z == 1 ? "\"yes\"" : "\"no\"");
      if (ps.scale_yz != 1.0) line("scale", real(ps.scale_yz));
    }
    if (ps.smooth != 0.0) line("smooth", real(ps.smooth));
    static constexpr const char* smoothing[] = {"spline", "weighted_spline", "weighted_bspline"};
    if (ps.ismooth != 0) line("smoothing", quote(smoothing[std::clamp(ps.ismooth, 0, 2)]));
    line("zigzag_threshold_rad", real(ps.zigthrs));
    line("kink_high_rad", real(ps.kinkhigh));
    line("kink_low_rad", real(ps.kinklow));
    line("kink_window_mm", real(ps.kinkwid));
    line("max_omitted", real(ps.maxomit));
  }

  void wheel_rail() {
    table("case.wheel_rail");
    static constexpr std::array<const char*, 6> sides{"\"left\"",        "\"right\"",       "", "",
                                                      "\"left_roller\"", "\"right_roller\""};
    line("side", sides[static_cast<std::size_t>(std::clamp(r_.config, 0, 5))]);
    if (r_.digits.n == 1) line("vertical_force_N", real(r_.motion.fz));
    if (r_.digits.f == 1) line("longitudinal_force_N", real(r_.motion.fx));
    if (r_.digits.f == 2) line("pitch_moment_Nmm", real(r_.motion.my));
    const WheelRailDiscretisation& ds = r_.discretisation;
    table("case.wheel_rail.discretisation");
    line("element_size_mm", real_array(std::array<double, 2>{ds.dx, ds.ds}));
    static constexpr const char* search[] = {
        "", "", "\"locus\"", "", "\"conformal\"", "\"brute_force\""};
    if (ds.method == 2 || ds.method == 4 || ds.method == 5) line("search", search[ds.method]);
    line("step_rel", real(ds.dqrel));
    line("separation_angle_rad", real(ds.a_sep));
    line("separation_mm", real(ds.d_sep));
    line("combination_mm", real(ds.d_comb));
    line("turning_mm", real(ds.d_turn));
    line("near_miss_mm", real(ds.g_miss));
    if (r_.digits.gapwgt == 1) line("gap_weights", "\"linear\"");
    line("max_elements", fmt::format("{}", r_.npot_max));
    const TrackDimensions& t = r_.track;
    table("case.wheel_rail.track");
    if (t.gaught > 0.0) {
      line("gauge_height_mm", real(t.gaught));
      line("gauge_width_mm", real(t.gaugwd));
    } else {
      line("rail_origin_mm", real_array(std::array<double, 2>{t.raily0, t.railz0}));
    }
    line("cant_rad", real(t.cant));
    line("curvature_per_mm", real(t.curv));
    if (t.nomradr != 0.0) line("roller_radius_mm", real(t.nomradr));
    const RailDeviations& dev = r_.rail_deviations;
    table("case.wheel_rail.rail_deviations");
    line("dy_mm", real(dev.dy));
    line("dz_mm", real(dev.dz));
    line("roll_rad", real(dev.droll));
    line("vy_mm_per_s", real(dev.vy));
    line("vz_mm_per_s", real(dev.vz));
    line("vroll_rad_per_s", real(dev.vroll));
    if (r_.digits.f == 3 && r_.has_massless_rail) {
      const MasslessRail& mr = r_.massless_rail;
      table("case.wheel_rail.massless_rail");
      line("ky_N_per_mm", real(mr.ky));
      line("fy_N", real(mr.fy));
      line("kz_N_per_mm", real(mr.kz));
      line("fz_N", real(mr.fz));
      line("dy_step_mm", real(mr.dystep0));
    }
    profile("rail", r_.rail);
    const WheelsetDimensions& w = r_.wheelset;
    table("case.wheel_rail.wheelset");
    line("flange_back_distance_mm", real(w.fbdist));
    line("flange_back_position_mm", real(w.fbpos));
    line("nominal_radius_mm", real(w.nomradw));
    line("tape_circle_y_mm", real(w.ytape));
    profile("wheel", r_.wheel);
    const WheelsetMotion& m = r_.motion;
    table("case.wheel_rail.position");
    line("s_mm", real(m.s));
    line("y_mm", real(m.y));
    if (r_.digits.n == 0) line("z_mm", real(m.z));
    line("roll_rad", real(m.roll));
    line("yaw_rad", real(m.yaw));
    line("pitch_rad", real(m.pitch));
    table("case.wheel_rail.velocity");
    line("forward_mm_per_s", real(m.vs));
    line("y_mm_per_s", real(m.vy));
    line("z_mm_per_s", real(m.vz));
    line("roll_rad_per_s", real(m.vroll));
    line("yaw_rad_per_s", real(m.vyaw));
    line("pitch_rad_per_s", real(m.vpitch));
    if (m.rpitch != 0.0) line("roller_pitch_rad_per_s", real(m.rpitch));
    // A flexible wheelset: its deviations (read with E = 4, 5 and kept by later cases).
    const WheelDeviations& d = r_.wheel_deviations;
    if (d.any_above(0.0)) {
      table("case.wheel_rail.wheel_deviation");
      line("dx_mm", real(d.dx));
      line("dy_mm", real(d.dy));
      line("dz_mm", real(d.dz));
      line("roll_rad", real(d.droll));
      line("yaw_rad", real(d.dyaw));
      line("pitch_rad", real(d.dpitch));
      line("vx_mm_per_s", real(d.vx));
      line("vy_mm_per_s", real(d.vy));
      line("vz_mm_per_s", real(d.vz));
      line("vroll_rad_per_s", real(d.vroll));
      line("vyaw_rad_per_s", real(d.vyaw));
      line("vpitch_rad_per_s", real(d.vpitch));
    }
  }

  std::string& out_;
  const WheelRailRecord& r_;
  CaseRecord id_ = settings_record(r_);
  const std::filesystem::path& base_dir_;
};

}  // namespace

std::string write_toml_string(const std::vector<CaseRecord>& problems,
                              const std::filesystem::path& base_dir) {
  std::vector<InputCase> cases(problems.begin(), problems.end());
  return write_toml_input_string(cases, base_dir);
}

std::string write_toml_input_string(const std::vector<InputCase>& cases,
                                    const std::filesystem::path& base_dir) {
  std::string out =
      "# rollcontact case file (docs/case-files.md). Units: mm, N, N/mm² (MPa), s, rad.\n";
  out += fmt::format("version = {}\n", toml_schema::version);
  for (const InputCase& c : cases) {
    if (const auto* p = std::get_if<CaseRecord>(&c))
      CaseWriter(out, *p, base_dir).write();
    else
      WheelRailWriter(out, std::get<WheelRailRecord>(c), base_dir).write();
  }
  return out;
}

void write_toml_file(const std::filesystem::path& path, const std::vector<CaseRecord>& problems) {
  write_file_atomically(path, write_toml_string(problems, path.parent_path()));
}

void write_toml_input_file(const std::filesystem::path& path, const std::vector<InputCase>& cases) {
  write_file_atomically(path, write_toml_input_string(cases, path.parent_path()));
}

}  // namespace rollcontact::format
