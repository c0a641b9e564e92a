// A wheel/rail case (module 1) in a TOML case file: a [[case]] with a [case.wheel_rail] table
// (docs/case-files.md). The shared sections (solver, friction, material, output, subsurface,
// heat, damping) are read by the module-3 section readers; the wheel/rail tables here. The
// result is the WheelRailRecord the .inp reader builds, so both go through the same adapter.

#include "format/toml/toml_wheelrail.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <string>

#include "format/inp/inp_blocks.hpp"
#include "format/inp/profile_spec_checks.hpp"
#include "format/profiles/profile_points.hpp"
#include "format/profiles/profile_reader.hpp"
#include "format/text/file_names.hpp"
#include "format/toml/toml_sections.hpp"

namespace rollcontact::format::toml_input {

namespace {

constexpr std::array<schema::Choice, 4> side_choices{
    {{0, "left"}, {1, "right"}, {4, "left_roller"}, {5, "right_roller"}}};
constexpr std::array<schema::Choice, 3> search_choices{
    {{2, "locus"}, {4, "conformal"}, {5, "brute_force"}}};
constexpr std::array<schema::Choice, 2> gap_weight_choices{{{0, "squared"}, {1, "linear"}}};
constexpr std::array<schema::Choice, 3> mirror_z_choices{{{0, "auto"}, {-1, "no"}, {1, "yes"}}};
constexpr std::array<schema::Choice, 3> smoothing_choices{
    {{0, "spline"}, {1, "weighted_spline"}, {2, "weighted_bspline"}}};

/// A profile table: `file` (relative to the TOML file; a profile or a slices file) or
/// `points = { y_mm, z_mm }`, and the options of the .inp profile lines.
ProfileSpec read_profile(Table& w, std::string_view key, bool is_wheel, double gauge_height_mm,
                         const Context& ctx, std::vector<std::string>& warnings) {
  Table t = w.table(key);
  ProfileSpec ps;
  ps.mirror_y = t.boolean_or("mirror_y", false) ? 1 : 0;
  ps.mirror_z = t.choice_or("mirror_z", mirror_z_choices, 0);
  ps.scale_yz = std::max(1e-6, t.real_or("scale", 1.0));
  ps.smooth = std::max(0.0, t.real_or("smooth", 0.0));
  ps.ismooth = t.choice_or("smoothing", smoothing_choices, 0);
  ps.zigthrs = std::max(t.real_or("zigzag_threshold_rad", ps.zigthrs), std::numbers::pi / 4.0);
  ps.kinkhigh = t.real_or("kink_high_rad", ps.kinkhigh);
  ps.kinklow = t.real_or("kink_low_rad", ps.kinkhigh / 5.0);
  ps.kinkwid = t.real_or("kink_window_mm", ps.kinkwid);
  ps.maxomit = t.real_or("max_omitted", ps.maxomit);
  if (ps.maxomit < 0.0 || ps.maxomit > 1.0)
    t.fail_key("max_omitted", fmt::format("{} outside [0, 1]", ps.maxomit));
  ProfileOptions options{is_wheel, ps.mirror_y, ps.mirror_z, ps.scale_yz};
  const auto file = t.opt_text("file");
  auto points = t.opt_table("points");
  if (file.has_value() == points.has_value())
    t.fail("give the profile as file = \"...\" or as points = { y_mm = [...], z_mm = [...] }");
  if (file) {
    ps.file = *file;
    const std::filesystem::path path = resolve_input_name(ctx.base_dir, *file);
    ps.path = path.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec))
      t.fail_key("file", fmt::format("profile file '{}' not found", *file));
    // Variable profiles (spec/inp-format.md §8.4): wheel slices around the axle, rail slices
    // along the track (which place the rail by rail_origin_mm).
    if (profile_format_of(path) == ProfileFormat::Slices) {
      switch (slices_file_problem(path, is_wheel, gauge_height_mm)) {
        case SlicesFileProblem::none:
          break;
        case SlicesFileProblem::wrong_extension:
          t.fail_key("file",
                     fmt::format("a {} profile needs a {} slices file", is_wheel ? "wheel" : "rail",
                                 is_wheel ? ".slcw" : ".slcs"));
        case SlicesFileProblem::rail_with_gauge_point:
          t.fail_key("file",
                     "rail slices (.slcs) need track.rail_origin_mm instead of a gauge height");
      }
    }
    load_profile(ps, path, options, warnings);
  } else {
    RawProfile raw;
    raw.file = t.key_path("points");
    raw.y = points->reals("y_mm");
    raw.z = points->reals("z_mm");
    if (raw.y.size() != raw.z.size() || raw.y.size() < 2)
      points->fail("y_mm and z_mm need the same number (at least 2) of values");
    points->finish();
    ps.file = raw.file;
    ps.profile = std::make_shared<const Profile>(finish_profile(raw, options, warnings));
  }
  if (const InadmissibleLength bad = first_inadmissible_length(ps); bad.profile != nullptr)
    t.fail(
        fmt::format("the {} profile has a length of {:.6g} mm, outside 5..500 mm (check scale "
                    "= {} or the file's units)",
                    is_wheel ? "wheel" : "rail", bad.chord_mm, ps.scale_yz));
  t.finish();
  return ps;
}

void read_discretisation(Table& w, WheelRailRecord& r, bool case_level_gap_weighting) {
  Table t = w.table("discretisation");
  WheelRailDiscretisation& d = r.discretisation;
  const std::vector<double> size = t.reals("element_size_mm", 2);
  d.dx = size[0];
  d.ds = size[1];
  if (!(d.dx >= 1e-8 && d.ds >= 1e-8)) t.fail_key("element_size_mm", "must be positive");
  d.method = t.choice_or("search", search_choices, 2);
  d.dqrel = t.real_or("step_rel", 1.0);
  if (d.dqrel < 5e-7 || d.dqrel > 10.0)
    t.fail_key("step_rel", fmt::format("{} outside [5e-7, 10]", d.dqrel));
  d.a_sep = std::max(0.0, t.real_or("separation_angle_rad", std::numbers::pi / 2.0));
  d.d_sep = std::max(0.0, t.real_or("separation_mm", 8.0));
  d.d_comb = std::max(0.0, t.real_or("combination_mm", 4.0));
  if (d.d_comb > d.d_sep) t.fail_key("combination_mm", "must not exceed separation_mm");
  d.d_turn = t.real_or("turning_mm", 2.0 * d.d_sep - d.d_comb);
  d.g_miss = t.real_or("near_miss_mm", -1.0);
  // GAPWGT: here or as the case's gap_weighting (docs/case-files.md names both); not both.
  if (t.has("gap_weights")) {
    const int here = t.choice_or("gap_weights", gap_weight_choices, 0);
    if (case_level_gap_weighting && here != r.digits.gapwgt)
      t.fail_key("gap_weights", "contradicts the case's gap_weighting; give one of the two");
    r.digits.gapwgt = here;
  }
  r.npot_max = t.integer_in("max_elements", r.npot_max, 100, 1000000);
  t.finish();
}

void read_track(Table& w, WheelRailRecord& r) {
  Table t = w.table("track");
  TrackDimensions& k = r.track;
  const auto height = t.opt_real("gauge_height_mm");
  const auto origin = t.opt_reals("rail_origin_mm", 2);
  if (height.has_value() == origin.has_value())
    t.fail("give gauge_height_mm (with gauge_width_mm) or rail_origin_mm = [y, z]");
  if (height) {
    k.gaught = *height;
    if (!(k.gaught > 0.0)) t.fail_key("gauge_height_mm", "must be positive");
    k.gaugwd = t.real("gauge_width_mm");
  } else {
    k.gaught = 0.0;
    k.raily0 = (*origin)[0];
    k.railz0 = (*origin)[1];
    t.forbid("gauge_width_mm", "with gauge_height_mm only");
  }
  k.cant = t.real_or("cant_rad", 0.0);
  k.curv = t.real_or("curvature_per_mm", 0.0);
  k.nomradr = t.real_or("roller_radius_mm", 0.0);
  t.finish();
  if (auto dev = w.opt_table("rail_deviations")) {
    RailDeviations& d = r.rail_deviations;
    d.dy = dev->real_or("dy_mm", 0.0);
    d.dz = dev->real_or("dz_mm", 0.0);
    d.droll = dev->real_or("roll_rad", 0.0);
    d.vy = dev->real_or("vy_mm_per_s", 0.0);
    d.vz = dev->real_or("vz_mm_per_s", 0.0);
    d.vroll = dev->real_or("vroll_rad_per_s", 0.0);
    dev->finish();
  }
}

void read_wheelset(Table& w, WheelRailRecord& r) {
  Table t = w.table("wheelset");
  WheelsetDimensions& d = r.wheelset;
  d.fbdist = t.real("flange_back_distance_mm");
  d.fbpos = t.real("flange_back_position_mm");
  d.nomradw = std::max(1e-3, t.real("nominal_radius_mm"));
  d.ytape = t.real_or("tape_circle_y_mm", 1000.0);
  t.finish();
}

/// Position, velocity and the vertical loading (force given, or the height z in position).
void read_motion(Table& w, WheelRailRecord& r) {
  WheelsetMotion& m = r.motion;
  Table p = w.table("position");
  m.s = p.real_or("s_mm", 0.0);
  m.y = p.real_or("y_mm", 0.0);
  const auto z = p.opt_real("z_mm");
  m.roll = p.real_or("roll_rad", 0.0);
  m.yaw = p.real_or("yaw_rad", 0.0);
  m.pitch = p.real_or("pitch_rad", 0.0);
  p.finish();
  const auto fz = w.opt_real("vertical_force_N");
  if (fz.has_value() == z.has_value())
    w.fail("give vertical_force_N (the height is solved for) or position.z_mm, not both");
  r.digits.n = fz ? 1 : 0;
  if (fz) {
    m.fz = *fz;
    if (!(m.fz >= 0.0)) w.fail_key("vertical_force_N", "must not be negative");
  } else {
    m.z = *z;
  }
  // F=1: the longitudinal force on the rail instead of the pitch velocity, which is solved for.
  if (const auto fx = w.opt_real("longitudinal_force_N")) {
    if (!fz) w.fail_key("longitudinal_force_N", "needs vertical_force_N (N=1), not position.z_mm");
    m.fx = *fx;
    r.digits.f = 1;
  }
  // F=2: the pitch moment on the rail about the axle instead, VPITCH solved for.
  if (const auto my = w.opt_real("pitch_moment_Nmm")) {
    if (!fz) w.fail_key("pitch_moment_Nmm", "needs vertical_force_N (N=1), not position.z_mm");
    if (r.digits.f == 1)
      w.fail_key("pitch_moment_Nmm", "and longitudinal_force_N exclude each other");
    m.my = *my;
    r.digits.f = 2;
  }
  Table v = w.table("velocity");
  m.vs = v.real_or("forward_mm_per_s", 0.0);
  m.vy = v.real_or("y_mm_per_s", 0.0);
  m.vz = v.real_or("z_mm_per_s", 0.0);
  m.vroll = v.real_or("roll_rad_per_s", 0.0);
  m.vyaw = v.real_or("yaw_rad_per_s", 0.0);
  m.vpitch = v.real_or("pitch_rad_per_s", 0.0);
  m.rpitch = v.real_or("roller_pitch_rad_per_s", 0.0);
  v.finish();
}

/// A flexible wheelset (E=5, spec/wheelrail-advanced.md §5.1): the wheel's deviations from its
/// place on the wheelset and their rates, in wheelset coordinates.
void read_wheel_deviation(Table& w, WheelRailRecord& r) {
  auto t = w.opt_table("wheel_deviation");
  if (!t) return;
  WheelDeviations& d = r.wheel_deviations;
  d.dx = t->real_or("dx_mm", 0.0);
  d.dy = t->real_or("dy_mm", 0.0);
  d.dz = t->real_or("dz_mm", 0.0);
  d.droll = t->real_or("roll_rad", 0.0);
  d.dyaw = t->real_or("yaw_rad", 0.0);
  d.dpitch = t->real_or("pitch_rad", 0.0);
  d.vx = t->real_or("vx_mm_per_s", 0.0);
  d.vy = t->real_or("vy_mm_per_s", 0.0);
  d.vz = t->real_or("vz_mm_per_s", 0.0);
  d.vroll = t->real_or("vroll_rad_per_s", 0.0);
  d.vyaw = t->real_or("vyaw_rad_per_s", 0.0);
  d.vpitch = t->real_or("vpitch_rad_per_s", 0.0);
  t->finish();
  r.digits.e = 5;  // the wheelset and wheel profile are given with it
}

/// The massless rail (F=3, spec/wheelrail-advanced.md §2): its springs and loads.
void read_massless_rail(Table& w, WheelRailRecord& r) {
  auto t = w.opt_table("massless_rail");
  if (!t) return;
  MasslessRail& m = r.massless_rail;
  m.ky = t->real("ky_N_per_mm");
  m.fy = t->real_or("fy_N", 0.0);
  m.kz = t->real_or("kz_N_per_mm", 0.0);
  m.fz = t->real_or("fz_N", 0.0);
  m.dystep0 = t->real_or("dy_step_mm", 1.0);
  if (!(m.dystep0 > 0.0)) t->fail_key("dy_step_mm", "must be positive");
  if (r.digits.t == 0) t->fail("the massless rail needs a tangential problem (not \"none\")");
  if (r.digits.n != 1 && !(std::abs(m.kz) >= 1e-10))
    t->fail_key("kz_N_per_mm",
                "must not be 0 with position.z_mm given (or give vertical_force_N instead)");
  t->finish();
  if (r.digits.f == 1)
    t->fail("the massless rail and longitudinal_force_N (F=1) exclude each other");
  r.digits.f = 3;
  r.has_massless_rail = true;
}

}  // namespace

WheelRailRecord read_wheelrail_case(Table& c, const Context& ctx, const std::string& file,
                                    int case_number) {
  // The shared sections through the module-3 readers, into a scratch record.
  CaseRecord shared;
  shared.source.file = file;
  // The tangential problem first: the material and heat sections check their models against it.
  if (auto t = c.opt_table("tangential")) {
    shared.digits.t = t->choice_or("problem", schema::tangential_problem, 3);
    t->finish();  // creepages come from the wheelset's motion
  } else {
    shared.digits.t = 3;
  }
  VariableFriction variation;
  read_solver(c, shared);
  read_friction(c, shared, &variation);
  if (!shared.friction.rows.empty())  // V=3: the grid rows of a module-3 problem
    c.fail(
        "friction.rows (one set per grid row, V=3) is a module-3 option; along a wheel/rail "
        "contact give friction.along with points (V=1, 2)");
  read_material(c, ctx, shared, true);
  if (shared.materials.influence_type == 9)  // C=9: one coefficient matrix, not per patch
    c.fail(
        "material.influence = \"from_file\" is a module-3 option: each wheel/rail patch "
        "has its own grid");
  read_damping(c, shared);
  read_heat(c, shared);
  read_subsurface(c, shared);
  read_output(c, shared);

  WheelRailRecord r;
  r.source.file = file;
  r.source.first_line = c.line();
  r.case_number = case_number;
  r.result_element = c.integer_in("result_element", 0, 0, 999);
  c.forbid("contact_problem", "module 1 finds its contact patches itself");
  (void)c.opt_text("name");  // a label for humans
  ControlDigits& d = r.digits;
  d = shared.digits;
  d.r = c.boolean_or("solve", true) ? 1 : 3;
  // A sequence of wheel/rail cases continues from the previous one as module 3 does (P, I);
  // the first case of a result element starts a new one (spec/inp-format.md §3.2).
  d.p = c.choice_or("previous_state", schema::previous_state, 2);
  d.i = c.choice_or("initial_estimate", schema::initial_estimate, 0);
  if (case_number == 1)
    start_new_sequence(d, fmt::format("result element {}", r.result_element), r.source.warnings);
  const bool case_level_gap_weighting = c.has("gap_weighting");
  d.gapwgt = c.choice_or("gap_weighting", schema::gap_weighting, 0);
  d.g = shared.solver.method;
  if (shared.solver.method == 5) r.source.warnings.push_back(kGdSteadyNote);
  d.d = 2;
  d.z = 3;
  d.e = 3;
  if (auto t = c.opt_table("normal")) {
    d.b = t->choice_or("method", schema::normal_method, 0);
    if (d.b == 2 || d.b == 3 || d.b == 4)
      t->fail_key("method",
                  "elliptic, parabolic and SDEC pressures are module-3 methods (B=2, "
                  "3, 4); wheel/rail patches take exact, exact_with_layer, kpec, analyn");
    if (d.b == 1) {  // B=1: the compressible interface layer's flexibility FLXZ
      shared.materials.flxz = t->real("layer_flexibility_mm3_per_N");
      if (!(shared.materials.flxz > 0.0))
        t->fail_key("layer_flexibility_mm3_per_N",
                    fmt::format("{} must be positive", shared.materials.flxz));
    } else {
      t->forbid("layer_flexibility_mm3_per_N", "only with method = \"exact_with_layer\"");
    }
    t->finish();  // the load is the wheelset's: wheel_rail.vertical_force_N or position.z_mm
  }
  r.solver = shared.solver;
  r.friction = shared.friction;
  r.variable_friction = variation;
  r.materials = shared.materials;
  r.damping = shared.damping;
  r.heat = shared.heat;
  r.subsurface = shared.subsurface;

  Table w = c.table("wheel_rail");
  r.config = w.choice_or("side", side_choices, 1);
  read_discretisation(w, r, case_level_gap_weighting);
  read_track(w, r);
  r.rail = read_profile(w, "rail", false, r.track.gaught, ctx, r.source.warnings);
  read_wheelset(w, r);
  r.wheel = read_profile(w, "wheel", true, r.track.gaught, ctx, r.source.warnings);
  read_motion(w, r);
  read_wheel_deviation(w, r);
  read_massless_rail(w, r);
  w.finish();
  c.finish();
  return r;
}

}  // namespace rollcontact::format::toml_input
