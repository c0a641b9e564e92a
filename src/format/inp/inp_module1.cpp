#include "format/inp/inp_module1.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <initializer_list>
#include <numbers>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include "format/inp/inp_blocks.hpp"
#include "format/inp/inp_control.hpp"
#include "format/inp/profile_spec_checks.hpp"
#include "format/profiles/profile_points.hpp"
#include "format/profiles/profile_reader.hpp"
#include "format/text/file_names.hpp"
#include "format/text/inp_checks.hpp"
#include "rollcontact/errors.hpp"
#include "rollcontact/model/validation.hpp"

namespace rollcontact::format {

namespace {

constexpr FieldKind kInt = FieldKind::integer;
constexpr FieldKind kReal = FieldKind::real;
constexpr FieldKind kAngle = FieldKind::angle;

constexpr double kMinElementSize = model::kMinElementSize_mm;  // DX, DS [mm]
constexpr int kDefaultNpotMax = 20000;

/// Names of the law values after the V=1,2 prefix (spec §4.1).
std::vector<std::string_view> friction_value_names(int law) {
  switch (law) {
    case 0:
      return {"FSTAT", "FKIN"};
    case 2:
      return {"FKIN", "FLIN1", "SABSH1", "FLIN2", "SABSH2"};
    case 3:
      return {"FKIN", "FRAT1", "SABSH1", "FRAT2", "SABSH2"};
    case 4:
      return {"FKIN", "FEXP1", "SABSH1", "FEXP2", "SABSH2"};
    default:
      return {"FREF", "TREF", "DFHEAT", "DTHEAT"};
  }
}

/// One V=1,2 friction line `ALPHA|SVF <law values>`: the prefix and the law values, checked as
/// read_friction_values() checks an unprefixed line.
std::pair<double, FrictionValues> read_prefixed_friction(InpStream& in, int v, int law, int k) {
  const std::vector<std::string_view> names = friction_value_names(law);
  const std::string what = fmt::format("friction set {} (V={}: {} {})", k, v,
                                       v == 1 ? "ALPHA" : "SVF", fmt::join(names, " "));
  const FieldSpec prefix{v == 1 ? "ALPHA" : "SVF", v == 1 ? kAngle : kReal};
  const GroupValues g = names.size() == 2
                            ? in.read_group({prefix, {names[0], kReal}, {names[1], kReal}}, what)
                        : names.size() == 4 ? in.read_group({prefix,
                                                             {names[0], kReal},
                                                             {names[1], kReal},
                                                             {names[2], kReal},
                                                             {names[3], kReal}},
                                                            what)
                                            : in.read_group({prefix,
                                                             {names[0], kReal},
                                                             {names[1], kReal},
                                                             {names[2], kReal},
                                                             {names[3], kReal},
                                                             {names[4], kReal}},
                                                            what);
  FrictionValues fv;
  if (law == 0) {
    fv.fstat = g.real(1);
    fv.fkin = g.real(2);
    check_coulomb_values(in, fv, g.line(1), g.line(2));
  } else if (law == 6) {
    fv.fkin = g.real(1);
    fv.fstat = fv.fkin;
    fv.params = {g.real(2), g.real(3), g.real(4), 0.0};
  } else {
    fv.fkin = g.real(1);
    fv.params = {g.real(2), g.real(3), g.real(4), g.real(5)};
    fv.fstat = fv.fkin + fv.params[0] + fv.params[2];
    require_at_least(in, g.line(1), "FKIN", fv.fkin, 0.0);
  }
  return {g.real(0), fv};
}

/// NPOT_MAX of the iteration line, clamped to 100..1e6 (default when absent).
int clamp_npot_max(std::optional<int> given, std::vector<std::string>& warnings) {
  if (!given) return kDefaultNpotMax;
  const int npot = std::clamp(*given, 100, 1000000);
  if (npot != *given) warnings.push_back(fmt::format("NPOT_MAX = {} clamped to {}", *given, npot));
  return npot;
}

/// The case being read: the stream, the record, the stored state of its result element, the
/// digits of the previous case and the lines of the control words.
struct CaseContext {
  InpStream& in;
  WheelRailRecord& p;
  Module1Stored& st;
  bool first;  ///< the first case of this result element
  ControlDigits previous_digits;
  int l1, l2, l3;
  std::string element;  ///< "result element R" for messages
};

/// Consistency rules that depend on the digits only (spec/inp-format.md §3.2); C=0 becomes 1.
void check_digits(CaseContext& c) {
  InpStream& in = c.in;
  ControlDigits& d = c.p.digits;
  const ControlDigits& prev = c.previous_digits;
  apply_shared_digit_rules(in, d, c.first, prev.v, c.st.has_subsurface, c.element, c.l1, c.l2,
                           "discretisation", "no discretisation is stored yet, use D=2..9",
                           c.p.source.warnings);
  if (!c.first && (prev.t >= 2) != (d.t >= 2) && d.c == 0) {
    in.fail(c.l2, fmt::format("switching from T={} to T={} (rolling <-> non-rolling) requires C≠0",
                              prev.t, d.t));
  }
  if (!c.first && d.e == 0 && d.n != prev.n) {
    in.fail(c.l2, fmt::format("E=0 (keep wheelset) while N changes from {} to {}: the vertical "
                              "position/force line must be read (use E≥1)",
                              prev.n, d.n));
  }
  if (d.f == 1 && d.n != 1) in.fail(c.l1, "F=1 (prescribed FX_WS) requires N=1");
  if (d.f == 2 && d.n != 1) in.fail(c.l1, "F=2 (prescribed MY_WS) requires N=1");
  if (d.f == 3 && d.t == 0)
    in.fail(c.l1, "F=3 (massless rail) requires a tangential problem: T=0 is not allowed");
  if (d.c == 0) {
    c.p.source.warnings.push_back(
        "C=0 overridden to 1 (influence coefficients are recomputed when needed)");
    d.c = 1;
  }
  if (d.c == 1 && !c.st.has_materials) {
    in.fail(c.l2, fmt::format("C=1 keeps the materials, but no material block was read for {} "
                              "(use C=2, 3 or 4)",
                              c.element));
  }
  check_rolling_model_digits(in, d, c.st.has_heat, c.element, c.l2, c.l3);
  if ((d.z == 0 || d.z == 1 || d.z == 2) && !c.st.has_rail) {
    in.fail(c.l2, fmt::format("Z={} keeps the rail profile, but none was read for {} (use Z=3)",
                              d.z, c.element));
  }
  if ((d.e == 0 || d.e == 1 || d.e == 2 || d.e == 4) && !c.st.has_wheel) {
    in.fail(c.l2, fmt::format("E={} keeps the wheel profile, but none was read for {} (use E=3 "
                              "or 5)",
                              d.e, c.element));
  }
}

/// V=1, 2: NVF friction sets at strictly increasing control points (angle or arc length).
void read_variable_friction(InpStream& in, const ControlDigits& d, WheelRailRecord& p) {
  const GroupValues g = in.read_group({{"NVF", kInt}}, "the friction variation line (NVF)");
  require_int_range(in, g.line(0), "NVF", g.integer(0), 1, kMaxFrictionSets);
  auto& vf = p.variable_friction;
  for (int k = 1; k <= g.integer(0); ++k) {
    const auto [position, values] = read_prefixed_friction(in, d.v, d.l, k);
    if (!vf.positions.empty() && !(position > vf.positions.back())) {
      in.fail(in.last_line(),
              fmt::format("friction control points must be strictly increasing: {} = {} "
                          "follows {}",
                          d.v == 1 ? "ALPHA" : "SVF", position, vf.positions.back()));
    }
    vf.positions.push_back(position);
    vf.sets.push_back(values);
  }
  assign_friction_values(vf.sets.front(), p.friction);
}

/// Lines 7-8: the friction law (L=1 keeps it), and the rules that tie it to H and M.
void read_friction_law(CaseContext& c) {
  InpStream& in = c.in;
  const ControlDigits& d = c.p.digits;
  WheelRailRecord& p = c.p;
  if (d.l != 1) {
    p.friction.law = d.l;
    p.friction.rows.clear();
    p.variable_friction = VariableFriction{};
    p.variable_friction.v = d.v;
    if (d.v == 0) {
      const FrictionValues fv =
          read_friction_values(in, d.l,
                               fmt::format("the friction line (L={}: {})", d.l,
                                           fmt::join(friction_value_names(d.l), " ")));
      assign_friction_values(fv, p.friction);
    } else {
      read_variable_friction(in, d, p);
    }
    if (friction_law_has_memory(d.l)) read_friction_memory(in, p.friction);
  }
  check_friction_law_digits(in, d, p.friction.law, c.l2);
}

/// Lines 9-12: conformal method (C=4, no inclination table in module 1), materials (body 1 =
/// rail, body 2 = wheel), damping and heat.
void read_materials_damping_heat(CaseContext& c) {
  InpStream& in = c.in;
  const ControlDigits& d = c.p.digits;
  WheelRailRecord& p = c.p;
  if (d.c == 4) {
    const GroupValues g =
        in.read_group({{"IF_METH", kInt}, {"VARIANT", kInt}}, "the C=4 line (IF_METH VARIANT)");
    require_int_range(in, g.line(0), "IF_METH", g.integer(0), 0, 1);
    require_int_range(in, g.line(1), "VARIANT", g.integer(1), 1, 4);
    p.materials.conformal = {};
    p.materials.conformal.if_meth = g.integer(0);
    p.materials.conformal.variant = g.integer(1);
  }
  if (d.c >= 2) {
    read_material_block(in, d.b, d.m, p.materials);
    p.materials.influence_type = d.c;
    c.st.has_materials = true;
  }
  if (d.m2 == 0) p.damping.enabled = false;
  if (d.m2 == 2) read_damping_line(in, p.damping);
  if (d.h == 3) {
    read_heat_lines(in, d.m == 4, p.heat);
    c.st.has_heat = true;
  }
}

/// Line 13 (D ≥ 2): the discretisation of the contact search and the patches.
void read_discretisation(CaseContext& c) {
  InpStream& in = c.in;
  const ControlDigits& d = c.p.digits;
  WheelRailRecord& p = c.p;
  const GroupValues g = in.read_group({{"DX", kReal},
                                       {"DS", kReal},
                                       {"DQREL", kReal},
                                       {"A_SEP", kAngle},
                                       {"D_SEP", kReal},
                                       {"D_COMB", kReal},
                                       {"D_TURN", kReal, true},
                                       {"G_MISS", kReal, true}},
                                      "the discretisation line (DX DS DQREL A_SEP D_SEP D_COMB)");
  WheelRailDiscretisation ds;
  ds.method = d.d;
  if (const std::string note = contact_search_note(d.d); !note.empty())
    p.source.warnings.push_back(note);
  ds.dx = g.real(0);
  ds.ds = g.real(1);
  ds.dqrel = g.real(2);
  if (!(ds.dx >= kMinElementSize)) {
    in.fail(g.line(0), fmt::format("DX = {} must be at least 1e-8", ds.dx));
  }
  if (!(ds.ds >= kMinElementSize)) {
    in.fail(g.line(1), fmt::format("DS = {} must be at least 1e-8", ds.ds));
  }
  require_real_range(in, g.line(2), "DQREL", ds.dqrel, 5e-7, 10.0);
  ds.a_sep = std::max(0.0, g.real(3));
  ds.d_sep = std::max(0.0, g.real(4));
  ds.d_comb = g.real(5);
  if (!(ds.d_sep >= ds.d_comb)) {
    in.fail(g.line(5), fmt::format("D_SEP = {} must be at least D_COMB = {}", ds.d_sep, ds.d_comb));
  }
  ds.d_turn = g.has(6) ? g.real(6) : 2.0 * ds.d_sep - ds.d_comb;
  ds.g_miss = g.has(7) ? g.real(7) : -1.0;
  if (!c.first && (d.t == 1 || d.t == 2) && c.st.has_discretisation &&
      (std::abs(ds.dx - p.discretisation.dx) > 1e-6 * p.discretisation.dx ||
       std::abs(ds.ds - p.discretisation.ds) > 1e-6 * p.discretisation.ds)) {
    in.fail(g.line(0),
            fmt::format("transient rolling (T={}): DX, DS = {}, {} must equal the previous {}, {}",
                        d.t, ds.dx, ds.ds, p.discretisation.dx, p.discretisation.ds));
  }
  p.discretisation = ds;
  c.st.has_discretisation = true;
}

/// Line 14 (Z=1, 3): the track dimensions (roller rigs: the roller radius instead of the cant).
void read_track_line(InpStream& in, WheelRailRecord& p) {
  const bool roller = p.is_roller();
  const GroupValues g = in.read_group({{"GAUGHT", kReal},
                                       {"G2", kReal},
                                       {"G3", kReal},
                                       {roller ? "NOMRADR" : "CANT", roller ? kReal : kAngle},
                                       {"CURV", kReal, true}},
                                      roller ? "the track line (GAUGHT G2 G3 NOMRADR {CURV})"
                                             : "the track line (GAUGHT G2 G3 CANT {CURV})");
  TrackDimensions& tr = p.track;
  tr = TrackDimensions{};
  tr.gaught = g.real(0);
  if (tr.gaught > 0.0) {
    tr.gaugsq = g.real(1);
    tr.gaugwd = g.real(2);
  } else {
    tr.raily0 = g.real(1);
    tr.railz0 = g.real(2);
  }
  if (roller) {
    tr.nomradr = g.real(3);
    // Negative: an internal roller (a ring around the wheel, spec/wheelrail-advanced.md §4.1).
    if (!(std::abs(tr.nomradr) >= 1.0))
      in.fail(g.line(3),
              fmt::format("NOMRADR = {} must be at least 1 mm in magnitude (negative: an internal "
                          "roller)",
                          tr.nomradr));
  } else {
    tr.cant = g.real(3);
  }
  tr.curv = g.has(4) ? g.real(4) : 0.0;
}

/// Lines 16-17 (Z=2, 3): rail deviations and, with F=3, the massless rail's stiffness.
/// Returns the line of the massless rail's data (0 when F≠3).
int read_rail_deviations(InpStream& in, const ControlDigits& d, WheelRailRecord& p) {
  const GroupValues g = in.read_group({{"DYRAIL", kReal},
                                       {"DZRAIL", kReal},
                                       {"DROLLR", kAngle},
                                       {"VYRAIL", kReal},
                                       {"VZRAIL", kReal},
                                       {"VROLLR", kAngle}},
                                      "the rail deviations line (DYRAIL DZRAIL DROLLR VYRAIL "
                                      "VZRAIL VROLLR)");
  p.rail_deviations = {g.real(0), g.real(1), g.real(2), g.real(3), g.real(4), g.real(5)};
  if (d.f == 3) {
    const GroupValues m = in.read_group({{"KYRAIL", kReal},
                                         {"FYRAIL", kReal},
                                         {"KZRAIL", kReal},
                                         {"FZRAIL", kReal},
                                         {"DYSTEP0", kReal, true}},
                                        "the massless rail line (KYRAIL FYRAIL KZRAIL FZRAIL)");
    p.massless_rail = {m.real(0), m.real(1), m.real(2), m.real(3), m.has(4) ? m.real(4) : 1.0};
    p.has_massless_rail = true;
    return m.line(2);
  }
  return 0;
}

/// Line 18 (E=3, 5): wheelset dimensions (the wheel profile line follows).
void read_wheelset_line(InpStream& in, WheelRailRecord& p) {
  const GroupValues g = in.read_group(
      {{"FBDIST", kReal}, {"FBPOS", kReal}, {"NOMRADW", kReal}, {"YTAPE", kReal, true}},
      "the wheelset line (FBDIST FBPOS NOMRADW {YTAPE})");
  p.wheelset = {g.real(0), g.real(1), g.real(2), g.has(3) ? g.real(3) : 1000.0};
  require_at_least(in, g.line(2), "NOMRADW", p.wheelset.nomradw, 1e-3);
}

/// Line 20 (E ≥ 1): wheelset position, with the vertical position or force (N).
void read_position_line(InpStream& in, const ControlDigits& d, WheelRailRecord& p) {
  WheelsetMotion& mo = p.motion;
  const bool roller = p.is_roller();
  const std::string_view p1 = roller ? "X_WS" : "S_WS";
  const std::string_view p3 = d.n == 0 ? "Z_WS" : "FZ";
  const GroupValues g =
      in.read_group({{p1, kReal},
                     {"Y_WS", kReal},
                     {p3, kReal},
                     {"ROLL", kAngle},
                     {"YAW", kAngle},
                     {"PITCH", kAngle}},
                    fmt::format("the wheelset position line ({} Y_WS {} ROLL YAW PITCH)", p1, p3));
  mo.s = g.real(0);
  mo.y = g.real(1);
  if (d.n == 0) {
    mo.z = g.real(2);
  } else {
    mo.fz = g.real(2);  // FZ < 1e-9 N: no contact computed, as in CONTACT (the solver says so)
  }
  mo.roll = g.real(3);
  mo.yaw = g.real(4);
  mo.pitch = g.real(5);
}

/// Line 21 (E ≥ 2): wheelset velocities (F=1: the longitudinal force instead of VPITCH); returns
/// the line of VS (RPITCH).
int read_velocity_line(InpStream& in, const ControlDigits& d, WheelRailRecord& p) {
  WheelsetMotion& mo = p.motion;
  const bool roller = p.is_roller();
  const std::string_view q1 = roller ? "RPITCH" : "VS";
  const std::string_view q6 = d.f == 1 ? "FX_WS" : d.f == 2 ? "MY_WS" : "VPITCH";
  const GroupValues g =
      in.read_group({{q1, roller ? kAngle : kReal},
                     {"VY", kReal},
                     {"VZ", kReal},
                     {"VROLL", kAngle},
                     {"VYAW", kAngle},
                     {q6, d.f == 1 || d.f == 2 ? kReal : kAngle}},
                    fmt::format("the wheelset velocity line ({} VY VZ VROLL VYAW {})", q1, q6));
  (roller ? mo.rpitch : mo.vs) = g.real(0);
  mo.vy = g.real(1);
  mo.vz = g.real(2);
  mo.vroll = g.real(3);
  mo.vyaw = g.real(4);
  (d.f == 1 ? mo.fx : d.f == 2 ? mo.my : mo.vpitch) = g.real(5);
  return g.line(0);
}

/// Viscoelastic bodies relax along +x only (spec-additions §B5, module 3's CHI = 0): a wheelset
/// rolling backwards on a track (VS < 0: χ = π in its patches) is refused, as module 3 refuses
/// CHI = π, instead of being solved as if it rolled forwards. (Roller rigs and a VS that the
/// wheel's rotation overrules are refused per patch, tangential/kinematics.cpp.)
void check_viscoelastic_rolling(InpStream& in, const ControlDigits& d, const WheelRailRecord& p,
                                int line) {
  if (d.m == 1 && !p.is_roller() && p.motion.vs < 0.0) {
    in.fail(line, fmt::format("M=1 (viscoelastic) requires rolling in +x (CHI = 0): VS = {:.6g} "
                              "mm/s rolls the wheelset backwards",
                              p.motion.vs));
  }
}

/// Line 22 (E=4, 5): deviations of a flexible wheel and their rates.
void read_flexible_wheel(InpStream& in, WheelRailRecord& p) {
  const GroupValues g1 = in.read_group({{"DXWHL", kReal},
                                        {"DYWHL", kReal},
                                        {"DZWHL", kReal},
                                        {"DROLLW", kAngle},
                                        {"DYAWW", kAngle},
                                        {"DPITCHW", kAngle}},
                                       "the flexible wheel line (DXWHL DYWHL DZWHL DROLLW DYAWW "
                                       "DPITCHW)");
  const GroupValues g2 = in.read_group({{"VXWHL", kReal},
                                        {"VYWHL", kReal},
                                        {"VZWHL", kReal},
                                        {"VROLLW", kAngle},
                                        {"VYAWW", kAngle},
                                        {"VPITCHW", kAngle}},
                                       "the flexible wheel rates line (VXWHL VYWHL VZWHL VROLLW "
                                       "VYAWW VPITCHW)");
  p.wheel_deviations = {g1.real(0), g1.real(1), g1.real(2), g1.real(3), g1.real(4), g1.real(5),
                        g2.real(0), g2.real(1), g2.real(2), g2.real(3), g2.real(4), g2.real(5)};
}

}  // namespace

WheelRailRecord Module1Reader::read_case(InpStream& in, int reid, int module_line,
                                         int case_number) {
  Module1Stored& st = stored_[reid];
  const bool first = !st.has_case;
  WheelRailRecord p = first ? WheelRailRecord{} : st.last;
  p.case_number = case_number;
  p.result_element = reid;
  p.source = SourceInfo{};
  p.source.file = in.file();
  p.source.module_line = module_line;

  // Lines 1-4: control words.
  const Module1Words cw = read_control_words_module1(in);
  const ControlDigits previous_digits = p.digits;
  p.digits = cw.digits;
  p.config = cw.config;
  p.source.digit_lines = cw.lines;
  p.source.first_line = cw.lines[0];
  CaseContext c{in,
                p,
                st,
                first,
                previous_digits,
                cw.lines[0],
                cw.lines[1],
                cw.lines[2],
                fmt::format("result element {}", reid)};
  const ControlDigits& d = p.digits;
  check_digits(c);

  if (d.g != 1) {  // lines 5-6 (G=1 keeps them)
    p.npot_max = clamp_npot_max(read_solver_lines(in, d.g, p.solver), p.source.warnings);
  }
  if (p.solver.method == 5) p.source.warnings.push_back(kGdSteadyNote);
  read_friction_law(c);                  // lines 7-8
  read_materials_damping_heat(c);        // lines 9-12
  if (d.d >= 2) read_discretisation(c);  // line 13

  // Lines 14-17: track, rail profile, rail deviations (massless rail).
  if (d.z == 1 || d.z == 3) read_track_line(in, p);
  if (d.z == 3) {
    p.rail = read_profile_line(in, /*is_wheel=*/false, p.track.gaught, p.source.warnings);
    st.has_rail = true;
  }
  const int massless_line = d.z == 2 || d.z == 3 ? read_rail_deviations(in, d, p) : 0;
  if (d.f == 3 && !p.has_massless_rail) {
    in.fail(c.l1, "F=3 (massless rail) needs the rail stiffness line: use Z=2 or 3");
  }
  if (d.f == 3 && d.n != 1 && !(std::abs(p.massless_rail.kz) >= 1e-10)) {
    // Without a vertical spring nothing fixes δz when z_ws is prescribed (spec §2.2).
    in.fail(d.z == 2 || d.z == 3 ? massless_line : c.l1,
            "F=3 (massless rail) with N=0 needs a vertical equation: KZRAIL must not be 0 "
            "(or prescribe the force, N=1)");
  }

  // Lines 18-22: wheelset, wheel profile, position, velocity, flexible wheel.
  if (d.e == 3 || d.e == 5) {
    read_wheelset_line(in, p);
    p.wheel = read_profile_line(in, /*is_wheel=*/true, p.track.gaught, p.source.warnings);
    st.has_wheel = true;
  }
  if (d.e >= 1) {
    read_position_line(in, d, p);
    st.has_position = true;
  }
  const int velocity_line = d.e >= 2 ? read_velocity_line(in, d, p) : c.l2;
  check_viscoelastic_rolling(in, d, p, velocity_line);
  if (d.e == 4 || d.e == 5) read_flexible_wheel(in, p);

  if (d.s >= 2) {  // line 23: subsurface points
    read_subsurface_block(in, d.s, p.subsurface, p.source.warnings);
    if (d.s == 3) st.has_subsurface = true;
  }

  st.last = p;
  st.has_case = true;
  return p;
}

ProfileSpec Module1Reader::read_profile_line(InpStream& in, bool is_wheel, double gaught,
                                             std::vector<std::string>& warnings) const {
  const char* body = is_wheel ? "wheel" : "rail";
  const GroupValues g = in.read_group({{"FNAME", FieldKind::string},
                                       {"MIRRORY", kInt},
                                       {"SCALEYZ", kReal},
                                       {"SMOOTH", kReal},
                                       {"MIRRORZ", kInt, true},
                                       {"PRFOPT", kInt, true}},
                                      fmt::format("the {} profile line ('FNAME' MIRRORY SCALEYZ "
                                                  "SMOOTH {{MIRRORZ {{PRFOPT}}}})",
                                                  body));
  ProfileSpec ps;
  ps.file = g.text(0);
  require_int_range(in, g.line(1), "MIRRORY", g.integer(1), -1, 1);
  ps.mirror_y = g.integer(1);
  ps.scale_yz = g.real(2);
  if (ps.scale_yz <= 1e-6) {
    warnings.push_back(fmt::format("{} profile: SCALEYZ = {} clamped to 1e-6", body, ps.scale_yz));
    ps.scale_yz = 1e-6;
  }
  ps.smooth = g.real(3);
  if (g.has(4)) {
    require_int_range(in, g.line(4), "MIRRORZ", g.integer(4), -1, 1);
    ps.mirror_z = g.integer(4);
  }
  if (g.has(5)) {
    require_int_range(in, g.line(5), "PRFOPT", g.integer(5), 0, 2);
    ps.prfopt = g.integer(5);
  }
  if (ps.prfopt >= 1) {
    const GroupValues o = in.read_group({{"ISMOOTH", kInt},
                                         {"ZIGTHRS", kAngle},
                                         {"KINKHIGH", kAngle},
                                         {"KINKLOW", kAngle},
                                         {"KINKWID", kReal}},
                                        "the profile options line (ISMOOTH ZIGTHRS KINKHIGH "
                                        "KINKLOW KINKWID)");
    ps.ismooth = std::clamp(o.integer(0), 0, 2);
    ps.zigthrs = std::max(o.real(1), std::numbers::pi / 4.0);
    ps.kinkhigh = o.real(2);
    ps.kinklow = o.real(3);
    ps.kinkwid = o.real(4);
  }
  if (ps.prfopt >= 2) {
    const GroupValues o = in.read_group({{"ERRHND", kInt}, {"MAXOMIT", kReal}},
                                        "the profile error line (ERRHND MAXOMIT)");
    require_int_range(in, o.line(0), "ERRHND", o.integer(0), -2, 1);
    require_real_range(in, o.line(1), "MAXOMIT", o.real(1), 0.0, 1.0);
    ps.errhnd = o.integer(0);
    ps.maxomit = o.real(1);
  }

  // The file itself, relative to the .inp folder.
  const int line = g.line(0);
  const std::filesystem::path path = resolve_input_name(base_dir_, ps.file);
  ps.path = path.string();
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) {
    in.fail(line, fmt::format("{} profile file '{}' not found (looked for {})", body, ps.file,
                              path.string()));
  }
  if (profile_format_of(path) == ProfileFormat::Slices) {
    switch (slices_file_problem(path, is_wheel, gaught)) {
      case SlicesFileProblem::none:
        break;
      case SlicesFileProblem::wrong_extension:
        in.fail(
            line,
            fmt::format("a {} profile needs a {} slices file", body, is_wheel ? ".slcw" : ".slcs"),
            ps.file);
      case SlicesFileProblem::rail_with_gauge_point:
        in.fail(line, fmt::format("a rail slices file (.slcs) requires GAUGHT ≤ 0, not {}", gaught),
                ps.file);
    }
  }
  ProfileOptions options;
  options.is_wheel = is_wheel;
  options.mirror_y = ps.mirror_y;
  options.mirror_z = ps.mirror_z;
  options.scale_yz = ps.scale_yz;
  try {
    load_profile(ps, path, options, warnings);
  } catch (const InputError& e) {
    // Errors inside the profile file name that file; say where it was asked for.
    throw InputError(
        e.file(), e.line(),
        fmt::format("{} ({} profile named at {}:{})", e.message(), body, in.file(), line),
        e.offending());
  }
  if (const InadmissibleLength bad = first_inadmissible_length(ps); bad.profile != nullptr) {
    in.fail(line,
            fmt::format("{} profile '{}' has a chord length of {:.6g} mm, outside 5..500 mm "
                        "(check SCALEYZ = {})",
                        body, bad.profile->file, bad.chord_mm, ps.scale_yz),
            ps.file);
  }
  return ps;
}

}  // namespace rollcontact::format
