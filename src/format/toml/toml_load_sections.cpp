// TOML case sections for the solver, the load, friction and materials (spec/results-json.md,
// docs/toml-input.md): each fills its part of a CaseRecord and checks it.

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "format/inp/grid_extent.hpp"
#include "format/inp/inp_blocks.hpp"
#include "format/inp/reader_checks.hpp"
#include "format/text/file_names.hpp"
#include "format/toml/toml_sections.hpp"

namespace rollcontact::format::toml_input {

void read_solver(Table& c, CaseRecord& p) {
  SolverSettings& s = p.solver;
  auto t = c.opt_table("solver");
  if (!t) return;
  s.method = t->choice_or("method", schema::solver_method, 0);
  s.maxgs = t->integer_in("max_inner_iterations", s.maxgs, 1, 9999);
  s.maxin = t->integer_in("max_outer_iterations", s.maxin, 1, 999999);
  s.maxnr = t->integer_in("max_newton_iterations", s.maxnr, 1, 9999);
  s.maxout = t->integer_in("max_coupling_iterations", s.maxout, 1, 9999);
  s.eps = t->real_or("tolerance", s.eps);
  if (!(s.eps > 0.0)) t->fail_key("tolerance", fmt::format("{} must be positive", s.eps));
  const bool omegas = s.method == 2 || s.method == 3;
  const bool slip = omegas || s.method == 4;
  if (omegas) {
    s.omega_h = t->real_or("omega_normal", s.omega_h);
    s.omega_s = t->real_or("omega_tangential", s.omega_s);
  } else {
    t->forbid("omega_normal", "only with method = \"convex_gs\" or \"steady_gs\"");
    t->forbid("omega_tangential", "only with method = \"convex_gs\" or \"steady_gs\"");
  }
  if (slip) {
    s.inislp = t->integer_or("initial_slip", s.inislp);
    s.omgslp = t->real_or("slip_relaxation", s.omgslp);
  } else {
    t->forbid("initial_slip", "only with methods convex_gs, steady_gs, default_with_slip_velocity");
    t->forbid("slip_relaxation",
              "only with methods convex_gs, steady_gs, default_with_slip_velocity");
  }
  if (s.method == 5) {
    if (auto gd = t->opt_table("gd_steady")) {
      s.gd.fdecay = gd->real_or("fdecay", 0.0);
      s.gd.betath = gd->real_or("betath", 0.0);
      s.gd.kdowfb = gd->integer_or("kdowfb", 0);
      s.gd.d_ifc = gd->real_or("d_ifc", 0.0);
      s.gd.d_lin = gd->real_or("d_lin", 0.0);
      s.gd.d_cns = gd->real_or("d_cns", 0.0);
      s.gd.d_slp = gd->real_or("d_slp", 0.0);
      s.gd.pow_s = gd->real_or("pow_s", 0.0);
      gd->finish();
    }
  } else {
    t->forbid("gd_steady", "only with method = \"gd_steady\"");
  }
  t->finish();
}

void read_normal(Table& c, CaseRecord& p) {
  Table t = c.table("normal");
  ControlDigits& d = p.digits;
  d.b = t.choice_or("method", schema::normal_method, 0);
  const auto force = t.opt_real("force_N");
  const auto approach = t.opt_real("approach_mm");
  if (force && approach) t.fail_key("approach_mm", "give either force_N or approach_mm, not both");
  if (!force && !approach) t.fail("missing the load: force_N or approach_mm");
  d.n = force ? 1 : 0;
  if (force) {
    p.kinematics.fn = *force;
    if (!(*force > 0.0)) t.fail_key("force_N", fmt::format("{} must be positive", *force));
  } else {
    p.kinematics.pen = *approach;
  }
  if (d.b == 1) {
    p.materials.flxz = t.real("layer_flexibility_mm3_per_N");
    if (!(p.materials.flxz > 0.0))
      t.fail_key("layer_flexibility_mm3_per_N",
                 fmt::format("{} must be positive", p.materials.flxz));
  } else {
    t.forbid("layer_flexibility_mm3_per_N", "only with method = \"exact_with_layer\"");
  }
  if (d.b == 4 && d.n != 1) t.fail_key("method", "\"sdec\" requires force_N (N=1)");
  if ((d.b == 5 || d.b == 6) && d.n != 0)
    t.fail_key("method", "\"kpec\" and \"analyn\" require approach_mm (N=0)");
  t.finish();
}

void read_tangential(Table& c, CaseRecord& p) {
  ControlDigits& d = p.digits;
  Kinematics& k = p.kinematics;
  auto t = c.opt_table("tangential");
  if (!t) return;
  d.t = t->choice_or("problem", schema::tangential_problem, 0);
  const bool shift = d.t == 1;
  const std::string_view x_name = shift ? "shift_x_mm" : "creepage_x";
  const std::string_view y_name = shift ? "shift_y_mm" : "creepage_y";
  const std::string_view spin_name = shift ? "rotation_rad" : "spin_rad_per_mm";
  t->forbid(shift ? "creepage_x" : "shift_x_mm",
            shift ? "use shift_x_mm for a shift" : "shift_x_mm is for problem = \"shift\"");
  t->forbid(shift ? "creepage_y" : "shift_y_mm",
            shift ? "use shift_y_mm for a shift" : "shift_y_mm is for problem = \"shift\"");
  t->forbid(shift ? "spin_rad_per_mm" : "rotation_rad",
            shift ? "use rotation_rad for a shift" : "rotation_rad is for problem = \"shift\"");
  const auto fx = t->opt_real("force_x_rel");
  const auto fy = t->opt_real("force_y_rel");
  const auto cx = t->opt_real(x_name);
  const auto cy = t->opt_real(y_name);
  if (fy && !fx) t->fail_key("force_y_rel", "needs force_x_rel as well (F=2)");
  if (fx && cx) t->fail_key(x_name, fmt::format("give either {} or force_x_rel, not both", x_name));
  if (fy && cy) t->fail_key(y_name, fmt::format("give either {} or force_y_rel, not both", y_name));
  d.f = fy ? 2 : fx ? 1 : 0;
  if (fx) {
    k.fx_rel = *fx;
    if (!(std::abs(*fx) <= 1.0))
      t->fail_key("force_x_rel", fmt::format("|{}| exceeds 1 (FX/(mu FN))", *fx));
  } else {
    k.cksi = cx.value_or(0.0);
  }
  if (fy) {
    k.fy_rel = *fy;
    const double ft2 = k.fx_rel * k.fx_rel + k.fy_rel * k.fy_rel;
    if (!(ft2 <= 1.0))
      t->fail_key("force_y_rel",
                  fmt::format("force_x_rel² + force_y_rel² = {:.6g} exceeds 1", ft2));
  } else {
    k.ceta = cy.value_or(0.0);
  }
  k.cphi = t->real_or(spin_name, 0.0);
  if (auto sc = t->opt_reals("spin_centre_mm", 2)) {
    k.spinxo = (*sc)[0];
    k.spinyo = (*sc)[1];
  }
  if (d.t >= 2) {
    Table r = t->table("rolling");
    k.chi = r.real_or("direction_rad", 0.0);
    k.dq = r.real("step_mm");
    k.veloc = r.real("velocity_mm_per_s");
    k.facphi = r.real_or("spin_offset_factor", 1.0 / 6.0);
    const double eps = p.solver.eps;
    if (!(k.dq >= eps))
      r.fail_key("step_mm", fmt::format("{} must be at least the tolerance {}", k.dq, eps));
    if (!(k.veloc >= eps)) {
      r.fail_key("velocity_mm_per_s",
                 fmt::format("{} must be at least the tolerance {}", k.veloc, eps));
    }
    r.finish();
  } else {
    t->forbid("rolling", "only with problem = \"transient_rolling\" or \"steady_rolling\"");
  }
  k.extra_slip_mode = t->choice_or("extra_slip", schema::extra_slip, 0);
  d.e = k.extra_slip_mode;
  if (k.extra_slip_mode == 9) {
    k.extra_slip = t->reals("extra_slip_per_element");
  } else {
    t->forbid("extra_slip_per_element", "only with extra_slip = \"per_element\"");
  }
  t->finish();
}

namespace {

FrictionValues read_friction_values(Table& t, int law) {
  FrictionValues fv;
  if (law == 0) {
    const auto st = t.opt_real("static");
    const auto kin = t.opt_real("kinetic");
    if (!st && !kin) t.fail("missing the Coulomb coefficient: kinetic (and/or static)");
    if (st && kin && std::abs(*st - *kin) > 1e-3 * std::abs(*kin)) {
      t.fail_key("static", fmt::format("Coulomb friction needs static = kinetic, but {} and {} "
                                       "differ by more than 0.1 %",
                                       *st, *kin));
    }
    fv.fkin = kin ? *kin : *st;
    fv.fstat = fv.fkin;
    if (fv.fkin < 1e-4 * (1.0 - 1e-12))
      t.fail_key(kin ? "kinetic" : "static", fmt::format("{} must be at least 0.0001", fv.fkin));
    return fv;
  }
  if (law == 6) {
    fv.fkin = t.real("reference");
    fv.fstat = fv.fkin;
    fv.params = {t.real("reference_temperature_C"), t.real("change"), t.real("temperature_span_C"),
                 0.0};
    return fv;
  }
  fv.fkin = t.real("kinetic");
  if (!(fv.fkin >= 0.0)) t.fail_key("kinetic", fmt::format("{} must be at least 0", fv.fkin));
  const auto excess = t.reals("excess", 2);
  const auto speed = t.reals("decay_speed_mm_per_s", 2);
  // A negative excess would make mu fall below FKIN and rise again; a negative decay speed
  // makes the term grow without bound with the slip velocity. 0 is a term switched off.
  for (std::size_t k = 0; k < 2; ++k) {
    if (!(excess[k] >= 0.0)) t.fail_key("excess", fmt::format("{} must be at least 0", excess[k]));
    if (!(speed[k] >= 0.0))
      t.fail_key("decay_speed_mm_per_s", fmt::format("{} must be at least 0", speed[k]));
  }
  fv.params = {excess[0], speed[0], excess[1], speed[1]};
  fv.fstat = fv.fkin + fv.params[0] + fv.params[2];
  return fv;
}

}  // namespace

namespace {

/// Friction along the track or with the rail's inclination (V=1, 2; wheel/rail cases only).
void read_friction_points(Table& t, int law, CaseRecord& p, VariableFriction* variation) {
  if (variation == nullptr)
    t.fail_key("points", "friction varying along the rail (V=1, 2) is for wheel/rail cases");
  constexpr std::array<schema::Choice, 2> along{{{1, "inclination"}, {2, "track"}}};
  const auto v = t.opt_choice("along", along);
  if (!v) t.fail("friction 'points' need 'along' (\"inclination\" or \"track\")");
  std::vector<Table> points = t.tables("points");
  if (points.empty()) t.fail_key("points", "needs at least one control point");
  if (points.size() > static_cast<std::size_t>(kMaxFrictionSets))
    t.fail_key("points", fmt::format("at most {} control points (NVF), found {}", kMaxFrictionSets,
                                     points.size()));
  *variation = VariableFriction{};
  variation->v = *v;
  for (Table& q : points) {
    const double at = q.real("at");
    if (!variation->positions.empty() && !(at > variation->positions.back()))
      q.fail_key("at", fmt::format("control points must be strictly increasing: {} follows {}", at,
                                   variation->positions.back()));
    variation->positions.push_back(at);
    variation->sets.push_back(read_friction_values(q, law));
    q.finish();
  }
  p.digits.v = *v;
  assign_friction_values(variation->sets.front(), p.friction);
}

}  // namespace

void read_friction(Table& c, CaseRecord& p, VariableFriction* variation) {
  Friction& f = p.friction;
  auto t = c.opt_table("friction");
  if (!t) return;  // CaseRecord's default: Coulomb 0.3
  f.law = t->choice_or("law", schema::friction_law, 0);
  p.digits.l = f.law;
  std::vector<Table> rows = t->tables("rows");
  if (t->has("points")) {
    read_friction_points(*t, f.law, p, variation);
  } else if (t->has("rows")) {
    if (rows.empty()) t->fail_key("rows", "needs one entry per grid row");
    p.digits.v = 3;
    for (Table& r : rows) {
      f.rows.push_back(read_friction_values(r, f.law));
      r.finish();
    }
    f.fstat = f.rows.front().fstat;
    f.fkin = f.rows.front().fkin;
    f.params = f.rows.front().params;
  } else {
    p.digits.v = 0;
    const FrictionValues fv = read_friction_values(*t, f.law);
    f.fstat = fv.fstat;
    f.fkin = fv.fkin;
    f.params = fv.params;
  }
  if (f.law == 2 || f.law == 3 || f.law == 4 || f.law == 6) {
    f.memdst = t->real_or("memory_distance_mm", 0.0);
    f.mem_s0 = t->real_or("memory_speed_mm_per_s", 0.0);
  } else {
    t->forbid("memory_distance_mm", "only with falling or temperature-dependent friction");
    t->forbid("memory_speed_mm_per_s", "only with falling or temperature-dependent friction");
  }
  t->finish();
}

namespace {

void read_body(Table& m, std::string_view key, double& poisson, double& modulus) {
  Table b = m.table(key);
  poisson = b.real("poisson");
  modulus = b.real("shear_modulus_MPa");
  if (!(poisson >= 0.0 && poisson <= 0.5))
    b.fail_key("poisson", fmt::format("{} outside [0, 0.5]", poisson));
  if (!(modulus >= 1e-5))
    b.fail_key("shear_modulus_MPa", fmt::format("{} must be at least 1e-05", modulus));
  b.finish();
}

}  // namespace

void read_material(Table& c, const Context& ctx, CaseRecord& p, bool wheel_rail) {
  Table t = c.table("material");
  Materials& m = p.materials;
  ControlDigits& d = p.digits;
  read_body(t, "body1", m.poiss1, m.gg1);
  read_body(t, "body2", m.poiss2, m.gg2);
  d.m = t.choice_or("model", schema::material_model, 0);
  m.influence_type = t.choice_or("influence", schema::influence, 2);
  d.c = m.influence_type;

  if (d.c == 9) {
    const auto file = t.opt_text("influence_file");
    if (!file) t.fail("missing required key 'influence_file' (influence = \"from_file\")");
    const std::filesystem::path resolved = resolve_input_name(ctx.base_dir, *file);
    m.influence_file = resolved.string();
    std::error_code ec;
    if (!std::filesystem::is_regular_file(resolved, ec)) {
      const std::string message = fmt::format("influence coefficient file '{}' not found", *file);
      if (ctx.options.missing_files_are_errors) t.fail_key("influence_file", message);
      p.source.case_error =
          fmt::format("{}:{}: {}", p.source.file, t.line("influence_file"), message);
    }
  } else {
    t.forbid("influence_file", "only with influence = \"from_file\"");
  }
  if (d.c == 4) {
    Table cf = t.table("conformal");
    auto& conf = m.conformal;
    conf.if_meth = cf.integer_in("method", 0, 0, 1);
    conf.variant = cf.integer_in("variant", 1, 1, 4);
    if (wheel_rail) {  // module 1: IF_METH VARIANT only (the .inp line has no pairs)
      cf.forbid("y_mm", "module 1 computes the inclinations of its patches");
      cf.forbid("inclination_rad", "module 1 computes the inclinations of its patches");
    } else {
      conf.y = cf.reals("y_mm");
      conf.alpha = cf.reals("inclination_rad");
      if (conf.y.empty() || conf.y.size() > 9999)
        cf.fail_key("y_mm", fmt::format("needs 1..9999 values, not {}", conf.y.size()));
      if (conf.alpha.size() != conf.y.size()) {
        cf.fail_key("inclination_rad", fmt::format("needs as many values as y_mm ({}), not {}",
                                                   conf.y.size(), conf.alpha.size()));
      }
    }
    cf.finish();
  } else {
    t.forbid("conformal", "only with influence = \"conformal\"");
  }

  m.model_params = {};
  if (d.m == 1) {
    Table v = t.table("viscoelastic");
    const auto fg = v.reals("modulus_factor", 2);
    const auto tc = v.reals("relaxation_time_s", 2);
    m.model_params = {fg[0], fg[1], tc[0], tc[1]};
    v.finish();
  } else {
    t.forbid("viscoelastic", "only with model = \"viscoelastic\"");
  }
  if (d.m == 2) {
    m.model_params[0] = t.real("flexibility_mm3_per_N");
    if (!(m.model_params[0] > 0.0))
      t.fail_key("flexibility_mm3_per_N", fmt::format("{} must be positive", m.model_params[0]));
  } else {
    t.forbid("flexibility_mm3_per_N", "only with model = \"fastsim_one_flexibility\"");
  }
  if (d.m == 2 || d.m == 3 || d.m == 5) {
    Table s = t.table("slope_reduction");
    const std::size_t o = d.m == 2 ? 1 : 0;
    m.model_params[o] = s.real("k0");
    m.model_params[o + 1] = s.real("alpha");
    m.model_params[o + 2] = s.real("beta");
    if (!(m.model_params[o] > 0.0))
      s.fail_key("k0", fmt::format("{} must be positive", m.model_params[o]));
    if (!(m.model_params[o + 1] >= 0.0))
      s.fail_key("alpha", fmt::format("{} must not be negative", m.model_params[o + 1]));
    if (!(m.model_params[o + 2] >= 0.0))
      s.fail_key("beta", fmt::format("{} must not be negative", m.model_params[o + 2]));
    s.finish();
  } else {
    t.forbid("slope_reduction", "only with the fastsim and fastrip models");
  }
  if (d.m == 4) {
    Table l = t.table("interfacial_layer");
    const double tau_c0 = l.real("yield_stress_MPa");
    // A critical stress this large means "no plasticity" (as in the .inp reader).
    m.model_params = {l.real("shear_modulus_MPa"), l.real("thickness_mm"),
                      tau_c0 >= 1e10 ? 0.0 : tau_c0, l.real("hardening_N_per_mm3")};
    l.finish();
  } else {
    t.forbid("interfacial_layer", "only with model = \"interfacial_layer\"");
  }
  if (d.m == 1 && d.t != 3) t.fail_key("model", "\"viscoelastic\" requires steady rolling (T=3)");
  if (d.m == 1 && std::abs(p.kinematics.chi) > 1e-9)
    t.fail_key("model", "\"viscoelastic\" requires rolling direction_rad = 0");
  t.finish();
}

void start_new_sequence(ControlDigits& d, const std::string& element,
                        std::vector<std::string>& warnings) {
  if (d.p != 2) {
    warnings.push_back(
        fmt::format("previous_state \"{}\" overridden to \"new\" in the first case of {}",
                    schema::name_of(schema::previous_state, d.p), element));
    d.p = 2;
  }
  if (d.i != 0) {
    warnings.push_back(
        fmt::format("initial_estimate \"{}\" overridden to \"none\" in the first case of {}",
                    schema::name_of(schema::initial_estimate, d.i), element));
    d.i = 0;
  }
}

}  // namespace rollcontact::format::toml_input
