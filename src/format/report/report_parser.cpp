// Reading `.out` / `.ref_out` reports (spec/validation.md §2). The reader only recognises label
// lines (they are stable across CONTACT versions and identical in our writer) and takes the
// numbers of the line below them by position; everything else — trace lines in particular, whose
// wording changes between versions — is skipped.

#include "format/report/report_parser.hpp"

#include <charconv>
#include <cmath>
#include <fstream>
#include <istream>
#include <limits>
#include <sstream>
#include <utility>

#include "format/text/input_file.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

std::optional<double> ReportCase::value(std::string_view name) const {
  const auto it = values.find(std::string(name));
  if (it == values.end()) return std::nullopt;
  return it->second;
}

const ReportCase* Report::find(int number) const {
  for (const auto& c : cases)
    if (c.number == number) return &c;
  return nullptr;
}

namespace {

constexpr double not_a_number = std::numeric_limits<double>::quiet_NaN();
// Field widths of the value lines (outputs.md §3.3/3.4): a run of asterisks this long is one
// overflowed field; adjacent overflowed fields merge into one token without a blank.
constexpr std::size_t real_field_width = 12;
constexpr std::size_t integer_field_width = 7;

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

std::vector<std::string_view> split_blanks(std::string_view s) {
  std::vector<std::string_view> out;
  std::size_t i = 0;
  while (i < s.size()) {
    while (i < s.size() && is_blank(s[i])) ++i;
    const std::size_t start = i;
    while (i < s.size() && !is_blank(s[i])) ++i;
    if (i > start) out.push_back(s.substr(start, i - start));
  }
  return out;
}

bool starts_with_blank(std::string_view line) {
  return !line.empty() && is_blank(line.front());
}

/// The labels of a label line. Only `CREEP X/Y` and `SHIFT X/Y` contain a blank, so they are
/// joined back; the long names of energy and friction work/power are shortened to the keys
/// documented in report_parser.hpp.
std::vector<std::string> split_labels(std::string_view line) {
  const auto words = split_blanks(line);
  std::vector<std::string> labels;
  for (std::size_t i = 0; i < words.size(); ++i) {
    std::string w(words[i]);
    if ((w == "CREEP" || w == "SHIFT") && i + 1 < words.size()) {
      w += ' ';
      w += words[++i];
    }
    if (w == "ELAST.EN.") w = "ELEN";
    if (w == "FRIC.POWER" || w == "FRIC.WORK") w = "FRIC";
    labels.push_back(std::move(w));
  }
  return labels;
}

enum class ValueKind { None, Reals, Integers };

/// Whether a label line announces a value line (validation.md §2 items 2–4).
ValueKind classify(const std::vector<std::string>& labels) {
  if (labels.size() < 2) return ValueKind::None;
  const std::string& first = labels[0];
  const std::string& second = labels[1];
  if (labels.size() >= 4 && (first == "FN" || first == "BAR_FN") &&
      (second == "FX" || second == "BAR_FX") && (labels[3] == "MZ" || labels[3] == "MN"))
    return ValueKind::Reals;
  if (first == "FN/G" || first == "TILDE_FN") return ValueKind::Reals;
  if (first == "FX(TR)" && second == "FY(TR)") return ValueKind::Reals;
  if (first == "NPOT" && second == "NCON") return ValueKind::Integers;
  // Module 1: contact reference location, kinematic constants, wheelset position.
  if ((first == "XCP(TR)" && second == "YCP(TR)") || (first == "XCP(W)" && second == "YCP(W)"))
    return ValueKind::Reals;
  if (first == "CHI" && second == "DQ") return ValueKind::Reals;
  if ((first == "S_WS" || first == "X_WS") && second == "Y_WS") return ValueKind::Reals;
  return ValueKind::None;
}

/// The numbers of a value line; nullopt when a token is neither a number nor asterisks (then the
/// line was not the value line we expected).
std::optional<std::vector<double>> parse_value_line(std::string_view line, std::size_t width) {
  std::vector<double> out;
  for (std::string_view token : split_blanks(line)) {
    std::size_t i = 0;
    while (i < token.size()) {
      const bool stars = token[i] == '*';
      std::size_t j = i;
      while (j < token.size() && (token[j] == '*') == stars) ++j;
      const std::string_view piece = token.substr(i, j - i);
      if (stars) {
        const std::size_t fields = std::max<std::size_t>(1, (piece.size() + width / 2) / width);
        out.insert(out.end(), fields, not_a_number);
      } else {
        const auto v = parse_report_real(piece);
        if (!v) return std::nullopt;
        out.push_back(*v);
      }
      i = j;
    }
  }
  if (out.empty()) return std::nullopt;
  return out;
}

/// `^ Case\s+(\d+)` → the number.
std::optional<int> case_header(std::string_view line) {
  constexpr std::string_view tag = " Case";
  if (line.substr(0, tag.size()) != tag) return std::nullopt;
  std::size_t i = tag.size();
  if (i >= line.size() || !is_blank(line[i])) return std::nullopt;
  while (i < line.size() && is_blank(line[i])) ++i;
  int number = 0;
  const auto [end, ec] = std::from_chars(line.data() + i, line.data() + line.size(), number);
  if (ec != std::errc() || end == line.data() + i) return std::nullopt;
  return number;
}

/// ` ----- DATA FOR CONTACT PATCH  k -----` → k.
std::optional<int> patch_header(std::string_view line) {
  constexpr std::string_view tag = "DATA FOR CONTACT PATCH";
  const auto at = line.find(tag);
  if (at == std::string_view::npos) return std::nullopt;
  const auto rest = split_blanks(line.substr(at + tag.size()));
  if (rest.empty()) return std::nullopt;
  int k = 0;
  const auto [end, ec] = std::from_chars(rest[0].data(), rest[0].data() + rest[0].size(), k);
  if (ec != std::errc() || end != rest[0].data() + rest[0].size()) return std::nullopt;
  return k;
}

/// ` SUBSURFACE STRESSES BLOCK  2:` → 2.
std::optional<int> subsurface_block_header(std::string_view line) {
  constexpr std::string_view tag = " SUBSURFACE STRESSES BLOCK";
  if (line.substr(0, tag.size()) != tag) return std::nullopt;
  std::string_view rest = line.substr(tag.size());
  while (!rest.empty() && rest.front() == ' ') rest.remove_prefix(1);
  int k = 0;
  const auto [end, ec] = std::from_chars(rest.data(), rest.data() + rest.size(), k);
  if (ec != std::errc() || end == rest.data()) return std::nullopt;
  return k;
}

/// ` MAX     SIGVM =   210.509 AT (X,Y,Z) = (...)` → {"SIGVM", 210.509}: one extreme of a
/// subsurface block (the location is not kept: near-equal maxima may sit in other elements).
std::optional<std::pair<std::string, double>> subsurface_extreme(std::string_view line) {
  const auto at = line.find(" AT (X,Y,Z)");
  const auto eq = line.find(" =");
  if (at == std::string_view::npos || eq == std::string_view::npos || eq > at) return std::nullopt;
  const auto words = split_blanks(line.substr(0, eq));
  if (words.size() != 2 || (words[0] != "MAX" && words[0] != "MIN" && words[0] != "ABSMAX"))
    return std::nullopt;
  const auto value = parse_report_real(split_blanks(line.substr(eq + 2, at - eq - 2)).front());
  if (!value) return std::nullopt;
  return std::pair{std::string(words[1]), *value};
}

}  // namespace

std::optional<double> parse_report_real(std::string_view token) {
  while (!token.empty() && is_blank(token.front())) token.remove_prefix(1);
  while (!token.empty() && is_blank(token.back())) token.remove_suffix(1);
  if (token.empty()) return std::nullopt;
  std::string s;
  bool has_digit = false, has_exponent = false;
  for (char c : token) {
    if (c == 'D' || c == 'd' || c == 'e') c = 'E';
    if (c >= '0' && c <= '9')
      has_digit = true;
    else if (c == 'E')
      has_exponent = true;
    else if (c != '.' && c != '+' && c != '-')
      return std::nullopt;  // from_chars takes "nan"
    s += c;
  }
  if (!has_digit) return std::nullopt;
  if (!has_exponent) {
    // Fortran drops the letter for three-digit exponents: `0.1000-100`.
    for (std::size_t i = 1; i < s.size(); ++i)
      if ((s[i] == '+' || s[i] == '-') && s[i - 1] != 'E') {
        s.insert(i, 1, 'E');
        break;
      }
  }
  std::size_t start = (s.front() == '+') ? 1 : 0;  // from_chars rejects a leading '+'
  double v = 0;
  const char* first = s.data() + start;
  const char* last = s.data() + s.size();
  const auto [end, ec] = std::from_chars(first, last, v);
  if (ec != std::errc() || end != last) return std::nullopt;
  return v;
}

Report parse_report(std::istream& in) {
  Report report;
  ReportCase* current = nullptr;
  std::string prefix;             // `patch k/` inside a module-1 patch block
  std::string subsurface_prefix;  // `SUBS k/` after a subsurface block's header
  std::vector<std::string> pending_labels;
  ValueKind pending = ValueKind::None;
  bool pending_case_level = false;
  bool in_error = false;

  std::string raw;
  while (std::getline(in, raw)) {
    std::string_view line(raw);
    while (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    if (!line.empty() && line.front() == '|') break;  // timing table: end of the last case

    if (const auto number = case_header(line)) {
      report.cases.emplace_back();
      current = &report.cases.back();
      current->number = *number;
      prefix.clear();
      subsurface_prefix.clear();
      pending = ValueKind::None;
      in_error = false;
      continue;
    }
    if (current == nullptr) continue;  // banner

    if (in_error) {
      // write_message() indents continuation lines by the width of " ERROR: ".
      constexpr std::string_view indent = "        ";
      if (line.substr(0, indent.size()) == indent && !split_blanks(line).empty()) {
        current->error += ' ';
        current->error += line.substr(indent.size());
        continue;
      }
      in_error = false;
    }
    constexpr std::string_view error_tag = " ERROR: ";
    if (line.substr(0, error_tag.size()) == error_tag) {
      current->error = std::string(line.substr(error_tag.size()));
      in_error = true;
      continue;
    }

    if (pending != ValueKind::None) {
      const std::size_t width =
          pending == ValueKind::Integers ? integer_field_width : real_field_width;
      if (const auto numbers = parse_value_line(line, width)) {
        const std::size_t n = std::min(numbers->size(), pending_labels.size());
        const std::string key_prefix = pending_case_level ? std::string() : prefix;
        for (std::size_t i = 0; i < n; ++i)
          current->values[key_prefix + pending_labels[i]] = (*numbers)[i];
        pending = ValueKind::None;
        continue;
      }
      pending = ValueKind::None;  // not a value line after all: read it as an ordinary line
    }

    if (const auto k = patch_header(line)) {
      prefix = "patch " + std::to_string(*k) + "/";
      subsurface_prefix.clear();
      continue;
    }
    if (const auto b = subsurface_block_header(line)) {
      subsurface_prefix = "SUBS " + std::to_string(*b) + "/";
      continue;
    }
    if (!subsurface_prefix.empty()) {
      if (const auto e = subsurface_extreme(line)) {
        current->values[prefix + subsurface_prefix + e->first] = e->second;
        continue;
      }
    }
    if (starts_with_blank(line)) {
      auto labels = split_labels(line);
      const ValueKind kind = classify(labels);
      if (kind != ValueKind::None) {
        // Module-1 totals over all patches belong to the case, wherever they are printed.
        pending_case_level = labels[0] == "FX(TR)" || labels[0] == "S_WS" || labels[0] == "X_WS";
        pending_labels = std::move(labels);
        pending = kind;
      }
    }
  }
  return report;
}

Report parse_report_file(const std::filesystem::path& path) {
  std::istringstream in(read_input_file(path, "report"));
  return parse_report(in);
}

}  // namespace rollcontact::format
