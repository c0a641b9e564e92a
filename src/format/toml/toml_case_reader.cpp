#include "format/toml/toml_case_reader.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

#include "format/inp/grid_extent.hpp"
#include "format/inp/reader_checks.hpp"
#include "format/toml/toml_case_schema.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

namespace schema = toml_schema;

constexpr long long kMaxElements = 2000000;  // MX*MY limit, as in the .inp reader
constexpr double kMinElementSize = 1e-8;     // DX, DY [mm]
constexpr int kMaxSubsurfaceBlocks = 10;
constexpr int kMaxSubsurfaceCount = 9999;

int line_of(const toml::node& n) {
  return static_cast<int>(n.source().begin.line);
}

std::string_view type_name(const toml::node& n) {
  switch (n.type()) {
    case toml::node_type::string:
      return "a string";
    case toml::node_type::integer:
      return "an integer";
    case toml::node_type::floating_point:
      return "a floating-point number";
    case toml::node_type::boolean:
      return "a boolean";
    case toml::node_type::table:
      return "a table";
    case toml::node_type::array:
      return "an array";
    default:
      return "a date/time";
  }
}

std::string choice_list(std::span<const schema::Choice> choices) {
  std::string s;
  for (const auto& c : choices) {
    if (!s.empty()) s += ", ";
    s += fmt::format("\"{}\"", c.name);
  }
  return s;
}

/// One TOML table being read: typed access by key, error messages with file, line and key path,
/// and the unknown-key check (every key a reader asks for counts as known).
class Table {
 public:
  Table(const toml::table& t, std::string path, const std::string& file)
      : t_(&t), path_(std::move(path)), file_(&file) {}

  std::string key_path(std::string_view key) const {
    return path_.empty() ? std::string(key) : fmt::format("{}.{}", path_, key);
  }
  int line() const { return line_of(*t_); }
  int line(std::string_view key) const {
    const toml::node* n = t_->get(key);
    return n ? line_of(*n) : line();
  }
  [[noreturn]] void fail_key(std::string_view key, const std::string& message) const {
    throw InputError(*file_, line(key), fmt::format("{}: {}", key_path(key), message));
  }
  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(*file_, line(),
                     fmt::format("{}: {}", path_.empty() ? "(top level)" : path_, message));
  }

  bool has(std::string_view key) {
    known_.emplace(key);
    return t_->contains(key);
  }
  const toml::node* get(std::string_view key) {
    known_.emplace(key);
    return t_->get(key);
  }
  /// A key that must not appear in this context (`why` says when it may).
  void forbid(std::string_view key, std::string_view why) {
    if (has(key)) fail_key(key, fmt::format("not allowed here: {}", why));
  }

  std::optional<double> opt_real(std::string_view key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    return to_real(*n, key_path(key));
  }
  double real(std::string_view key) {
    if (auto v = opt_real(key)) return *v;
    fail(fmt::format("missing required key '{}'", key));
  }
  double real_or(std::string_view key, double fallback) { return opt_real(key).value_or(fallback); }

  std::optional<int> opt_integer(std::string_view key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    return to_int(*n, key_path(key));
  }
  int integer(std::string_view key) {
    if (auto v = opt_integer(key)) return *v;
    fail(fmt::format("missing required key '{}'", key));
  }
  int integer_or(std::string_view key, int fallback) { return opt_integer(key).value_or(fallback); }
  int integer_in(std::string_view key, int fallback, int lo, int hi) {
    const int v = integer_or(key, fallback);
    if (v < lo || v > hi) fail_key(key, fmt::format("{} outside {}..{}", v, lo, hi));
    return v;
  }

  bool boolean_or(std::string_view key, bool fallback) {
    const toml::node* n = get(key);
    if (!n) return fallback;
    if (!n->is_boolean()) type_error(*n, key_path(key), "a boolean (true or false)");
    return n->as_boolean()->get();
  }

  std::optional<std::string> opt_text(std::string_view key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    if (!n->is_string()) type_error(*n, key_path(key), "a string");
    return n->as_string()->get();
  }

  std::optional<int> opt_choice(std::string_view key, std::span<const schema::Choice> choices) {
    const auto s = opt_text(key);
    if (!s) return std::nullopt;
    if (auto code = schema::code_of(choices, *s)) return code;
    fail_key(key, fmt::format("\"{}\" is not one of {}", *s, choice_list(choices)));
  }
  int choice_or(std::string_view key, std::span<const schema::Choice> choices, int fallback) {
    return opt_choice(key, choices).value_or(fallback);
  }

  std::optional<Table> opt_table(std::string_view key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    if (!n->is_table()) type_error(*n, key_path(key), "a table");
    return Table(*n->as_table(), key_path(key), *file_);
  }
  Table table(std::string_view key) {
    if (auto t = opt_table(key)) return *t;
    fail(fmt::format("missing required table '{}'", key));
  }
  /// An array of tables ([[x]] or [{...}, ...]); empty when absent.
  std::vector<Table> tables(std::string_view key) {
    std::vector<Table> out;
    const toml::node* n = get(key);
    if (!n) return out;
    if (!n->is_array()) type_error(*n, key_path(key), "an array of tables");
    const toml::array& a = *n->as_array();
    for (std::size_t k = 0; k < a.size(); ++k) {
      const std::string p = fmt::format("{}[{}]", key_path(key), k + 1);
      if (!a[k].is_table()) type_error(a[k], p, "a table");
      out.emplace_back(*a[k].as_table(), p, *file_);
    }
    return out;
  }

  std::optional<std::vector<double>> opt_reals(std::string_view key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    const toml::array& a = array_of(*n, key_path(key), "an array of numbers");
    std::vector<double> v(a.size());
    for (std::size_t k = 0; k < a.size(); ++k)
      v[k] = to_real(a[k], fmt::format("{}[{}]", key_path(key), k + 1));
    return v;
  }
  std::vector<double> reals(std::string_view key) {
    if (auto v = opt_reals(key)) return *v;
    fail(fmt::format("missing required key '{}'", key));
  }
  /// An array of exactly `n` numbers, or nothing when absent.
  std::optional<std::vector<double>> opt_reals(std::string_view key, std::size_t n) {
    auto v = opt_reals(key);
    if (v && v->size() != n)
      fail_key(key, fmt::format("expected {} numbers but found {}", n, v->size()));
    return v;
  }
  std::vector<double> reals(std::string_view key, std::size_t n) {
    if (auto v = opt_reals(key, n)) return *v;
    fail(fmt::format("missing required key '{}'", key));
  }
  std::optional<std::vector<int>> opt_integers(std::string_view key) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    const toml::array& a = array_of(*n, key_path(key), "an array of integers");
    std::vector<int> v(a.size());
    for (std::size_t k = 0; k < a.size(); ++k)
      v[k] = to_int(a[k], fmt::format("{}[{}]", key_path(key), k + 1));
    return v;
  }
  /// Arrays of arrays of numbers (e.g. rectangles), each inner array of length `inner`.
  std::optional<std::vector<std::vector<double>>> opt_real_rows(std::string_view key,
                                                                std::size_t inner) {
    const toml::node* n = get(key);
    if (!n) return std::nullopt;
    const toml::array& a = array_of(*n, key_path(key), "an array of arrays of numbers");
    std::vector<std::vector<double>> rows;
    for (std::size_t k = 0; k < a.size(); ++k) {
      const std::string p = fmt::format("{}[{}]", key_path(key), k + 1);
      const toml::array& r = array_of(a[k], p, "an array of numbers");
      if (r.size() != inner)
        throw InputError(*file_, line_of(a[k]),
                         fmt::format("{}: expected {} numbers but found {}", p, inner, r.size()));
      std::vector<double> row(inner);
      for (std::size_t j = 0; j < inner; ++j)
        row[j] = to_real(r[j], fmt::format("{}[{}]", p, j + 1));
      rows.push_back(std::move(row));
    }
    return rows;
  }

  /// Unknown keys are errors: a misspelt key must not silently fall back to a default.
  void finish() const {
    for (auto&& [k, v] : *t_) {
      if (known_.count(k.str()) == 0) {
        throw InputError(*file_, line_of(v),
                         fmt::format("{}: unknown key (expected one of: {})", key_path(k.str()),
                                     fmt::join(known_, ", ")));
      }
    }
  }

 private:
  [[noreturn]] void type_error(const toml::node& n, const std::string& path,
                               std::string_view expected) const {
    throw InputError(*file_, line_of(n),
                     fmt::format("{}: expected {} but found {}", path, expected, type_name(n)));
  }
  const toml::array& array_of(const toml::node& n, const std::string& path,
                              std::string_view expected) const {
    if (!n.is_array()) type_error(n, path, expected);
    return *n.as_array();
  }
  double to_real(const toml::node& n, const std::string& path) const {
    if (n.is_floating_point()) return n.as_floating_point()->get();
    if (n.is_integer()) return static_cast<double>(n.as_integer()->get());
    type_error(n, path, "a number");
  }
  int to_int(const toml::node& n, const std::string& path) const {
    if (!n.is_integer()) type_error(n, path, "an integer");
    const std::int64_t v = n.as_integer()->get();
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max()) {
      throw InputError(*file_, line_of(n), fmt::format("{}: integer {} is too large", path, v));
    }
    return static_cast<int>(v);
  }

  const toml::table* t_;
  std::string path_;
  const std::string* file_;
  std::set<std::string, std::less<>> known_;
};

std::size_t element_count(const PotentialContact& pc) {
  return static_cast<std::size_t>(pc.mx) * static_cast<std::size_t>(pc.my);
}

/// What the reader remembers across cases: the previous case per contact problem (for the
/// first-case overrides and the grid-continuity rule) and case numbers per result element.
struct Sequence {
  std::map<std::pair<int, int>, CaseRecord> last;
  std::map<int, int> case_counts;
};

/// Everything a case reader needs besides the case table.
struct Context {
  std::filesystem::path base_dir;
  TomlReadOptions options;
};

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
  fv.params = {excess[0], speed[0], excess[1], speed[1]};
  fv.fstat = fv.fkin + fv.params[0] + fv.params[2];
  return fv;
}

void read_friction(Table& c, CaseRecord& p) {
  Friction& f = p.friction;
  auto t = c.opt_table("friction");
  if (!t) return;  // CaseRecord's default: Coulomb 0.3
  f.law = t->choice_or("law", schema::friction_law, 0);
  p.digits.l = f.law;
  std::vector<Table> rows = t->tables("rows");
  if (t->has("rows")) {
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

void read_material(Table& c, const Context& ctx, CaseRecord& p) {
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
    const std::filesystem::path name(*file);
    const std::filesystem::path resolved =
        (name.is_absolute() || ctx.base_dir.empty()) ? name : ctx.base_dir / name;
    m.influence_file = resolved.lexically_normal().string();
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
    conf.y = cf.reals("y_mm");
    conf.alpha = cf.reals("inclination_rad");
    if (conf.y.empty() || conf.y.size() > 9999)
      cf.fail_key("y_mm", fmt::format("needs 1..9999 values, not {}", conf.y.size()));
    if (conf.alpha.size() != conf.y.size()) {
      cf.fail_key("inclination_rad", fmt::format("needs as many values as y_mm ({}), not {}",
                                                 conf.y.size(), conf.alpha.size()));
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
  } else {
    t.forbid("flexibility_mm3_per_N", "only with model = \"fastsim_one_flexibility\"");
  }
  if (d.m == 2 || d.m == 3 || d.m == 5) {
    Table s = t.table("slope_reduction");
    const std::size_t o = d.m == 2 ? 1 : 0;
    m.model_params[o] = s.real("k0");
    m.model_params[o + 1] = s.real("alpha");
    m.model_params[o + 2] = s.real("beta");
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

void check_elements(Table& g, PotentialContact& pc, int min_size) {
  const auto e = g.opt_integers("elements");
  if (!e) g.fail("missing required key 'elements' ([MX, MY])");
  if (e->size() != 2)
    g.fail_key("elements", fmt::format("expected 2 integers but found {}", e->size()));
  pc.mx = (*e)[0];
  pc.my = (*e)[1];
  if (pc.mx < min_size || pc.my < min_size)
    g.fail_key("elements",
               fmt::format("[{}, {}]: each must be at least {}", pc.mx, pc.my, min_size));
  const long long n = static_cast<long long>(pc.mx) * static_cast<long long>(pc.my);
  if (n > kMaxElements) g.fail_key("elements", fmt::format("MX·MY = {} exceeds 2 000 000", n));
}

void require_positive(Table& t, std::string_view key, double v) {
  if (!(v > 0.0)) t.fail_key(key, fmt::format("{} must be positive", v));
}

void read_grid(Table& c, CaseRecord& p) {
  Table t = c.table("grid");
  PotentialContact& pc = p.potential;
  const std::array<std::string_view, 4> kinds{"rectangle", "hertz", "hertz_2d", "sdec"};
  std::string_view kind;
  for (std::string_view k : kinds) {
    if (!t.has(k)) continue;
    if (!kind.empty()) t.fail_key(k, fmt::format("give only one of {}", fmt::join(kinds, ", ")));
    kind = k;
  }
  if (kind.empty()) t.fail(fmt::format("missing the grid: one of {}", fmt::join(kinds, ", ")));
  Table g = t.table(kind);
  pc.values = {};
  if (kind == "rectangle") {
    const auto ll = g.opt_reals("lower_left_mm", 2);
    const auto fc = g.opt_reals("first_centre_mm", 2);
    const auto es = g.opt_reals("element_size_mm", 2);
    const auto ur = g.opt_reals("upper_right_mm", 2);
    const auto lc = g.opt_reals("last_centre_mm", 2);
    const int corners = (ll ? 1 : 0) + (fc ? 1 : 0);
    const int sizes = (es ? 1 : 0) + (ur ? 1 : 0) + (lc ? 1 : 0);
    if (corners != 1 || sizes != 1 || (ll && lc) || (fc && ur)) {
      g.fail(
          "give lower_left_mm with element_size_mm or upper_right_mm, or first_centre_mm with "
          "element_size_mm or last_centre_mm");
    }
    const auto& a = ll ? *ll : *fc;
    const auto& b = es ? *es : ur ? *ur : *lc;
    pc.ipotcn = ll ? (es ? 1 : 2) : (es ? 3 : 4);
    pc.values = {a[0], a[1], b[0], b[1]};
    check_elements(g, pc, pc.ipotcn == 4 ? 2 : 1);
    const GridExtent ext = grid_extent(pc);
    if (!(ext.dx >= kMinElementSize) || !(ext.dy >= kMinElementSize)) {
      g.fail(fmt::format("element size DX, DY = {}, {} must be at least 1e-8 mm", ext.dx, ext.dy));
    }
  } else if (kind == "hertz") {
    check_elements(g, pc, 1);
    const double scale = g.real("scale");
    const auto curv = g.opt_reals("curvatures_per_mm", 2);
    const auto a1 = g.opt_real("curvature_x_per_mm");
    const auto aob = g.opt_real("semi_axis_ratio");
    const auto axes = g.opt_reals("semi_axes_mm", 2);
    if (curv && !a1 && !aob && !axes) {
      pc.ipotcn = -1;
      pc.values = {(*curv)[0], (*curv)[1], scale, 0.0};
    } else if (a1 && aob && !curv && !axes) {
      pc.ipotcn = -2;
      pc.values = {*a1, *aob, scale, 0.0};
    } else if (axes && !curv && !a1 && !aob) {
      pc.ipotcn = -3;
      pc.values = {(*axes)[0], (*axes)[1], scale, 0.0};
    } else {
      g.fail(
          "give curvatures_per_mm, or curvature_x_per_mm with semi_axis_ratio, or "
          "semi_axes_mm");
    }
    for (std::size_t k = 0; k < 3; ++k)
      if (!(pc.values[k] > 0.0))
        g.fail(fmt::format("the Hertz values and scale must be positive, not {}", pc.values[k]));
  } else if (kind == "hertz_2d") {
    check_elements(g, pc, 1);
    const double scale = g.real("scale");
    const double bb = g.real("half_width_mm");
    const auto a1 = g.opt_real("curvature_x_per_mm");
    const auto aa = g.opt_real("half_length_mm");
    if (a1.has_value() == aa.has_value())
      g.fail("give either curvature_x_per_mm or half_length_mm");
    pc.ipotcn = a1 ? -4 : -5;
    pc.values = {a1 ? *a1 : *aa, bb, scale, 0.0};
    for (std::size_t k = 0; k < 3; ++k)
      if (!(pc.values[k] > 0.0))
        g.fail(fmt::format("the Hertz values and scale must be positive, not {}", pc.values[k]));
  } else {
    check_elements(g, pc, 1);
    const double aa = g.real("semi_axis_x_mm");
    const auto bb = g.reals("half_width_mm", 2);
    const double scale = g.real("scale");
    pc.ipotcn = -6;
    pc.values = {aa, bb[0], bb[1], scale};
    for (double v : pc.values)
      if (!(v > 0.0)) g.fail(fmt::format("the SDEC values and scale must be positive, not {}", v));
  }
  g.finish();
  t.finish();

  const ControlDigits& d = p.digits;
  if ((d.b == 2 || d.b == 3) && pc.ipotcn > 0)
    t.fail("normal.method \"elliptic\" and \"parabolic\" need a Hertzian grid (hertz, hertz_2d)");
  if ((pc.ipotcn == -6) != (d.b == 4)) t.fail("grid.sdec and normal.method = \"sdec\" go together");
  if ((pc.ipotcn == -4 || pc.ipotcn == -5) && d.n != 1)
    t.fail("grid.hertz_2d requires normal.force_N (N=1)");
  if (pc.ipotcn <= -1 && pc.ipotcn >= -5 && d.n == 0 && p.kinematics.pen < 0.0) {
    t.fail(fmt::format("a Hertzian grid with approach_mm needs approach_mm >= 0, not {}",
                       p.kinematics.pen));
  }
}

void read_geometry(Table& c, CaseRecord& p) {
  const PotentialContact& pc = p.potential;
  UndeformedDistance& ud = p.geometry;
  ud = UndeformedDistance{};
  if (pc.ipotcn < 0) {
    c.forbid("geometry", "a Hertzian grid derives the undeformed distance itself");
    return;
  }
  Table t = c.table("geometry");
  const std::array<std::string_view, 4> kinds{"quadratic", "profile", "sines", "per_element_mm"};
  std::string_view kind;
  for (std::string_view k : kinds) {
    if (!t.has(k)) continue;
    if (!kind.empty()) t.fail_key(k, fmt::format("give only one of {}", fmt::join(kinds, ", ")));
    kind = k;
  }
  if (kind.empty())
    t.fail(fmt::format("missing the undeformed distance: one of {}", fmt::join(kinds, ", ")));
  if (kind == "quadratic") {
    ud.ibase = 1;
    ud.coeffs = t.reals("quadratic", 6);
  } else if (kind == "sines") {
    ud.ibase = 3;
    ud.coeffs = t.reals("sines", 8);
  } else if (kind == "per_element_mm") {
    ud.ibase = 9;
    ud.values = t.reals("per_element_mm", element_count(pc));
  } else {
    ud.ibase = 2;
    Table pr = t.table("profile");
    ud.coeffs = pr.reals("heights_mm");
    if (ud.coeffs.size() < 2) pr.fail_key("heights_mm", "needs at least 2 values");
    ud.y1 = pr.real("y_first_mm");
    ud.dy1 = pr.real("y_step_mm");
    require_positive(pr, "y_step_mm", ud.dy1);
    ud.xm = pr.real_or("x_centre_mm", 0.0);
    ud.rm = pr.real("x_radius_mm");
    pr.finish();
  }
  ud.iplan = 1;
  if (auto pl = t.opt_table("planform")) {
    const auto quad = pl->opt_reals("quadratic", 6);
    const auto two = pl->opt_real_rows("two_rectangles", 4);
    const auto patches = pl->opt_real_rows("patches", 4);
    if ((quad ? 1 : 0) + (two ? 1 : 0) + (patches ? 1 : 0) != 1)
      pl->fail("give one of quadratic, two_rectangles, patches");
    if (quad) {
      ud.iplan = 2;
      ud.planform = *quad;
    } else if (two) {
      ud.iplan = 3;
      if (two->size() != 2) pl->fail_key("two_rectangles", "needs exactly 2 rectangles");
      static constexpr std::array<std::string_view, 4> kLim{"xl", "xh", "yl", "yh"};
      for (std::size_t r = 0; r < 2; ++r) {
        const auto& rect = (*two)[r];
        for (std::size_t k = 0; k < 4; k += 2)
          if (rect[k] > rect[k + 1])
            pl->fail_key("two_rectangles",
                         fmt::format("rectangle {}: {} = {} exceeds {} = {}", r + 1, kLim[k],
                                     rect[k], kLim[k + 1], rect[k + 1]));
        ud.planform.insert(ud.planform.end(), rect.begin(), rect.end());
      }
    } else {
      ud.iplan = 4;
      if (patches->empty() || patches->size() > 9999)
        pl->fail_key("patches", "needs 1..9999 rectangles");
      ud.npatch = static_cast<int>(patches->size());
      for (const auto& rect : *patches)
        ud.planform.insert(ud.planform.end(), rect.begin(), rect.end());
      const std::size_t n = patches->size();
      const std::size_t nfac = n * (n - 1) / 2;
      if (nfac > 0) {
        ud.patch_factors = pl->reals("factors", nfac);
      } else {
        pl->forbid("factors", "needs at least 2 patches");
      }
    }
    if (!patches) pl->forbid("factors", "only with patches");
    pl->finish();
  }
  t.finish();
}

void read_output(Table& c, CaseRecord& p) {
  ControlDigits& d = p.digits;
  if (auto t = c.opt_table("output")) {
    d.o = t->integer_in("report_level", d.o, 0, 5);
    d.a = t->choice_or("mat_file", schema::mat_file, d.a);
    d.w = t->integer_in("trace_level", d.w, 0, 9);
    t->finish();
  }
  d.x = 0;
  d.debug = DebugDigits{};
  if (auto t = c.opt_table("debug")) {
    d.x = 1;
    d.debug.p = t->integer_in("profiles", 0, 0, 9);
    d.debug.s = t->integer_in("smoothing", 0, 0, 9);
    d.debug.f = t->integer_in("force_loop", 0, 0, 9);
    d.debug.l = t->integer_in("contact_search", 0, 0, 9);
    d.debug.c = t->integer_in("patches", 0, 0, 9);
    d.debug.i = t->integer_in("influence", 0, 0, 9);
    d.debug.n = t->integer_in("solver", 0, 0, 9);
    d.debug.readln = t->integer_or("input_echo", 0);
    t->finish();
  }
}

void read_damping(Table& c, CaseRecord& p) {
  p.damping = Damping{};
  p.digits.m2 = 0;
  auto t = c.opt_table("damping");
  if (!t) return;
  p.digits.m2 = 2;
  p.damping.enabled = true;
  p.damping.cdampn = t->real_or("normal_time_s", 0.0);
  p.damping.cdampt = t->real_or("tangential_time_s", 0.0);
  p.damping.dfnmax = t->real_or("max_normal_force_rate_N_per_s", 0.0);
  p.damping.dftmax = t->real_or("max_tangential_force_rate_N_per_s", 0.0);
  t->finish();
}

void read_heat_body(Table& t, std::string_view key, double& temp, double& cp, double& lambda,
                    double& dens) {
  Table b = t.table(key);
  temp = b.real("temperature_C");
  cp = b.real("heat_capacity_J_per_kg_C");
  lambda = b.real("conductivity_W_per_mm_C");
  dens = b.real("density_kg_per_mm3");
  b.finish();
}

void read_heat(Table& c, CaseRecord& p) {
  p.digits.h = 0;
  auto t = c.opt_table("heat");
  if (!t) return;
  p.digits.h = 3;
  HeatParameters& h = p.heat;
  read_heat_body(*t, "body1", h.bktemp1, h.heatcp1, h.lambda1, h.dens1);
  read_heat_body(*t, "body2", h.bktemp2, h.heatcp2, h.lambda2, h.dens2);
  if (p.digits.m == 4) {
    h.betapl = t->real_or("plastic_heat_fraction", 0.0);
    if (!(h.betapl >= 0.0 && h.betapl <= 1.0))
      t->fail_key("plastic_heat_fraction", fmt::format("{} outside [0, 1]", h.betapl));
  } else {
    t->forbid("plastic_heat_fraction", "only with material.model = \"interfacial_layer\"");
  }
  if (p.digits.t != 3) t->fail("temperature calculation requires steady rolling (T=3)");
  t->finish();
}

SubsurfaceBlock read_subsurface_block(Table& b) {
  SubsurfaceBlock s;
  auto count = [&](std::string_view key, std::size_t n) {
    if (n < 1 || n > static_cast<std::size_t>(kMaxSubsurfaceCount))
      b.fail_key(key, fmt::format("needs 1..{} values, not {}", kMaxSubsurfaceCount, n));
  };
  const bool points = b.has("x_mm") || b.has("y_mm");
  const bool ranges = b.has("columns") || b.has("rows");
  const bool lists = b.has("column_list") || b.has("row_list");
  if ((points ? 1 : 0) + (ranges ? 1 : 0) + (lists ? 1 : 0) > 1)
    b.fail("give one selection: columns/rows, column_list/row_list, or x_mm/y_mm");
  const bool z_list = b.has("z_mm");
  const bool z_range = b.has("z_first_mm") || b.has("z_step_mm") || b.has("z_count");
  if (z_list == z_range) b.fail("give either z_mm or z_first_mm, z_step_mm, z_count");
  if (points && !z_list) b.fail("points x_mm, y_mm need the depths as z_mm");
  if (points) {
    s.isubs = 9;
    s.x = b.reals("x_mm");
    s.y = b.reals("y_mm");
    count("x_mm", s.x.size());
    count("y_mm", s.y.size());
  } else if (ranges) {
    s.isubs = z_list ? 6 : 2;
    const auto cols = b.opt_integers("columns");
    const auto rows = b.opt_integers("rows");
    if (!cols || cols->size() != 3) b.fail("columns needs [first, step, last]");
    if (!rows || rows->size() != 3) b.fail("rows needs [first, step, last]");
    s.ixl = (*cols)[0];
    s.ixinc = (*cols)[1];
    s.ixh = (*cols)[2];
    s.iyl = (*rows)[0];
    s.iyinc = (*rows)[1];
    s.iyh = (*rows)[2];
    if (s.ixinc < 1 || s.ixinc > kMaxSubsurfaceCount) b.fail_key("columns", "step outside 1..9999");
    if (s.iyinc < 1 || s.iyinc > kMaxSubsurfaceCount) b.fail_key("rows", "step outside 1..9999");
  } else if (lists) {
    s.isubs = z_list ? 7 : 3;
    const auto ix = b.opt_integers("column_list");
    const auto iy = b.opt_integers("row_list");
    if (!ix || !iy) b.fail("column_list and row_list go together");
    count("column_list", ix->size());
    count("row_list", iy->size());
    s.ix = *ix;
    s.iy = *iy;
    for (auto* list : {&s.ix, &s.iy}) {
      std::sort(list->begin(), list->end());
      list->erase(std::unique(list->begin(), list->end()), list->end());
    }
  } else {
    s.isubs = z_list ? 5 : 1;
  }
  if (z_list) {
    s.z = b.reals("z_mm");
    count("z_mm", s.z.size());
  } else {
    const int nz = b.integer("z_count");
    count("z_count", static_cast<std::size_t>(std::max(nz, 0)));
    s.zl = b.real("z_first_mm");
    s.dz = b.real("z_step_mm");
    require_positive(b, "z_step_mm", s.dz);
    s.z.resize(static_cast<std::size_t>(nz));
    for (std::size_t k = 0; k < s.z.size(); ++k) s.z[k] = s.zl + static_cast<double>(k) * s.dz;
  }
  for (auto* list : {&s.x, &s.y, &s.z}) std::sort(list->begin(), list->end());
  b.finish();
  return s;
}

void read_subsurface(Table& c, CaseRecord& p) {
  p.digits.s = 0;
  p.subsurface = Subsurface{};
  auto t = c.opt_table("subsurface");
  if (!t) return;
  p.digits.s = 3;
  p.subsurface.matfil = t->choice_or("mat_file", schema::subsurface_file, 0);
  p.subsurface.output = t->integer_in("report", 0, 0, 4);
  std::vector<Table> blocks = t->tables("block");
  if (blocks.size() > static_cast<std::size_t>(kMaxSubsurfaceBlocks))
    t->fail_key("block", fmt::format("more than {} blocks", kMaxSubsurfaceBlocks));
  for (Table& b : blocks) p.subsurface.blocks.push_back(read_subsurface_block(b));
  t->finish();
}

/// Checks that need the grid: per-element arrays and friction rows.
void check_grid_sizes(Table& c, const CaseRecord& p) {
  const std::size_t n = element_count(p.potential);
  const Kinematics& k = p.kinematics;
  if (k.extra_slip_mode == 9 && k.extra_slip.size() != 2 * n) {
    Table t = c.table("tangential");
    t.fail_key("extra_slip_per_element",
               fmt::format("needs 2·MX·MY = {} values (wx, wy per element), not {}", 2 * n,
                           k.extra_slip.size()));
  }
  if (p.digits.v == 3 && p.friction.rows.size() != static_cast<std::size_t>(p.potential.my)) {
    Table t = c.table("friction");
    t.fail_key("rows", fmt::format("needs one entry per grid row (MY = {}), not {}", p.potential.my,
                                   p.friction.rows.size()));
  }
}

CaseRecord read_case(Table& c, const Context& ctx, Sequence& seq, const std::string& file) {
  CaseRecord p;
  p.source.file = file;
  p.source.first_line = c.line();
  ControlDigits& d = p.digits;
  auto warn = [&p](std::string text) { p.source.warnings.push_back(std::move(text)); };

  (void)c.opt_text("name");  // a label for humans; CaseRecord has no place for it
  p.result_element = c.integer_in("result_element", 0, 0, 999);
  p.contact_problem = c.integer_in("contact_problem", 1, 1, 9);
  d.r = c.boolean_or("solve", true) ? 1 : 3;
  d.p = c.choice_or("previous_state", schema::previous_state, 2);
  d.i = c.choice_or("initial_estimate", schema::initial_estimate, 0);
  d.gapwgt = c.choice_or("gap_weighting", schema::gap_weighting, 0);
  d.d = 2;
  d.z = 2;

  read_solver(c, p);
  d.g = p.solver.method;
  read_normal(c, p);
  read_tangential(c, p);
  read_friction(c, p);
  read_material(c, ctx, p);
  read_damping(c, p);
  read_heat(c, p);
  read_grid(c, p);
  read_geometry(c, p);
  read_subsurface(c, p);
  read_output(c, p);
  check_grid_sizes(c, p);
  if (p.friction.law == 6 && d.h == 0)
    c.fail("friction.law = \"temperature\" requires a [heat] table");
  if (p.friction.law == 6 && (d.m == 2 || d.m == 3 || d.m == 5 || d.m == 6 || d.m == 7))
    c.fail("friction.law = \"temperature\" is not allowed with this material.model");
  c.finish();

  const auto key = std::make_pair(p.result_element, p.contact_problem);
  const auto prev = seq.last.find(key);
  const std::string element = p.contact_problem == 1
                                  ? fmt::format("result element {}", p.result_element)
                                  : fmt::format("result element {} contact problem {}",
                                                p.result_element, p.contact_problem);
  if (prev == seq.last.end()) {
    if (d.p != 2) {
      warn(fmt::format("previous_state \"{}\" overridden to \"new\" in the first case of {}",
                       schema::name_of(schema::previous_state, d.p), element));
      d.p = 2;
    }
    if (d.i != 0) {
      warn(fmt::format("initial_estimate \"{}\" overridden to \"none\" in the first case of {}",
                       schema::name_of(schema::initial_estimate, d.i), element));
      d.i = 0;
    }
  } else if (d.p != 2 || d.i != 0) {
    // Continuing from the previous case needs the same elements, possibly shifted by whole ones.
    const GridExtent ext = grid_extent(p.potential);
    const GridExtent old = grid_extent(prev->second.potential);
    if (ext.known && old.known) {
      if (differs(ext.dx, old.dx, 1e-6) || differs(ext.dy, old.dy, 1e-6)) {
        c.fail(
            fmt::format("continuing from the previous case: element size {}, {} must equal "
                        "the previous {}, {}",
                        ext.dx, ext.dy, old.dx, old.dy));
      }
      if (!is_multiple(ext.xl - old.xl, old.dx) || !is_multiple(ext.yl - old.yl, old.dy)) {
        c.fail(
            fmt::format("continuing from the previous case: the grid offset ({:.6g}, {:.6g}) "
                        "must be a whole number of elements",
                        ext.xl - old.xl, ext.yl - old.yl));
      }
    }
  }
  if (p.solver.maxout > 1 && std::abs(material_k(p.materials)) < 1e-10) {
    warn(
        fmt::format("max_coupling_iterations = {} overridden to 1: the materials are "
                    "quasi-identical (K = 0)",
                    p.solver.maxout));
    p.solver.maxout = 1;
  }
  p.case_number = ++seq.case_counts[p.result_element];
  seq.last[key] = p;
  return p;
}

}  // namespace

std::vector<CaseRecord> read_toml_string(const std::string& text, const std::string& name,
                                         const std::filesystem::path& base_dir,
                                         const TomlReadOptions& options) {
  toml::table root;
  try {
    root = toml::parse(std::string_view(text), std::string_view(name));
  } catch (const toml::parse_error& e) {
    throw InputError(name, static_cast<int>(e.source().begin.line),
                     fmt::format("TOML syntax error: {}", e.description()));
  }
  Table top(root, "", name);
  if (auto v = top.opt_integer("version"); v && *v != toml_schema::version) {
    top.fail_key("version", fmt::format("case-file version {} is not supported (expected {})", *v,
                                        toml_schema::version));
  }
  std::vector<Table> cases = top.tables("case");
  top.finish();
  if (cases.empty()) top.fail("no [[case]] found");
  const Context ctx{base_dir, options};
  Sequence seq;
  std::vector<CaseRecord> problems;
  problems.reserve(cases.size());
  for (Table& c : cases) problems.push_back(read_case(c, ctx, seq, name));
  return problems;
}

std::vector<CaseRecord> read_toml_file(const std::filesystem::path& path,
                                       const TomlReadOptions& options) {
  std::ifstream file(path, std::ios::binary);
  if (!file) throw InputError(path.string(), 0, "cannot open input file");
  std::ostringstream text;
  text << file.rdbuf();
  return read_toml_string(text.str(), path.string(), path.parent_path(), options);
}

}  // namespace rollcontact::format
