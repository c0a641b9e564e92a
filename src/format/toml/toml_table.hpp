#pragma once
// Reading one TOML table of a case file: typed access by key, error messages with file, line and
// key path, and the unknown-key check. Shared by the section readers of toml_case_reader.

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "format/inp/case_record.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "format/toml/toml_case_schema.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format::toml_input {

namespace schema = toml_schema;

inline int line_of(const toml::node& n) {
  return static_cast<int>(n.source().begin.line);
}

inline std::string_view type_name(const toml::node& n) {
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

inline std::string choice_list(std::span<const schema::Choice> choices) {
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
                     fmt::format("{}: expected {} but found {}", path, expected, described(n)));
  }
  /// A node as a message shows it: a scalar with its value, else its kind.
  static std::string described(const toml::node& n) {
    if (const auto* s = n.as_string()) {
      const std::string& v = s->get();
      return fmt::format("the string \"{}{}\"", v.substr(0, 40), v.size() > 40 ? "…" : "");
    }
    if (const auto* i = n.as_integer()) return fmt::format("the integer {}", i->get());
    if (const auto* f = n.as_floating_point()) return fmt::format("the number {}", f->get());
    if (const auto* b = n.as_boolean()) return fmt::format("the boolean {}", b->get());
    return std::string(type_name(n));
  }
  const toml::array& array_of(const toml::node& n, const std::string& path,
                              std::string_view expected) const {
    if (!n.is_array()) type_error(n, path, expected);
    return *n.as_array();
  }
  double to_real(const toml::node& n, const std::string& path) const {
    if (n.is_floating_point()) {
      // TOML has inf and nan literals; no rollcontact input may be either (CONTACT's .inp
      // reader has no such numbers at all).
      const double v = n.as_floating_point()->get();
      if (!std::isfinite(v))
        throw InputError(*file_, line_of(n), fmt::format("{}: {} is not a finite number", path, v));
      return v;
    }
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

inline std::size_t element_count(const PotentialContact& pc) {
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

}  // namespace rollcontact::format::toml_input
