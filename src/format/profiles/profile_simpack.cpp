#include "format/profiles/profile_simpack.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <optional>

#include "format/profiles/profile_text.hpp"
#include "format/text/inp_lexer.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

enum class Section { None, Header, Spline, Points };

std::string lower(std::string_view s) {
  std::string out(s);
  std::transform(out.begin(), out.end(), out.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return out;
}

}  // namespace

RawProfile parse_simpack_profile(std::string_view text, const std::string& file, bool is_wheel,
                                 std::vector<std::string>& warnings) {
  RawProfile raw;
  raw.file = file;
  raw.format = ProfileFormat::Simpack;
  raw.min_spacing = 1e-4;
  const std::vector<std::string> lines = split_lines(text);
  auto fail = [&](std::size_t index, std::string message, std::string offending = {}) {
    throw InputError(file, static_cast<int>(index + 1), std::move(message), std::move(offending));
  };

  Section section = Section::None;
  bool header_seen = false;
  bool spline_seen = false;
  bool points_seen = false;
  bool finished = false;
  std::vector<double> row;
  std::string bad;
  std::size_t last_line = 0;
  for (std::size_t i = 0; i < lines.size() && !finished; ++i) {
    const std::string_view line = trim(strip_comment(lines[i], "!%"));
    if (line.empty()) continue;
    last_line = i;
    const std::string word = lower(line.substr(0, line.find_first_of(" \t=")));
    // Section markers.
    if (word == "header.begin" || word == "spline.begin" || word == "point.begin") {
      const Section want = word == "point.begin" ? Section::Spline : Section::None;
      if (section != want) fail(i, fmt::format("'{}' is not allowed here", word), word);
      section = word == "header.begin"   ? Section::Header
                : word == "spline.begin" ? Section::Spline
                                         : Section::Points;
      header_seen |= section == Section::Header;
      spline_seen |= section == Section::Spline;
      points_seen |= section == Section::Points;
      continue;
    }
    if (word == "header.end" || word == "point.end" || word == "spline.end") {
      const Section want = word == "header.end"  ? Section::Header
                           : word == "point.end" ? Section::Points
                                                 : Section::Spline;
      if (section != want) fail(i, fmt::format("'{}' without matching begin", word), word);
      section = word == "point.end" ? Section::Spline : Section::None;
      finished = word == "spline.end";  // reading stops at the first spline.end
      continue;
    }
    if (section == Section::Points) {
      if (!parse_number_row(line, row, bad) || row.size() < 2) {
        fail(i, "expected 'y z [weight]' numbers in the point section",
             bad.empty() ? std::string(line) : bad);
      }
      raw.y.push_back(row[0]);
      raw.z.push_back(row[1]);
      continue;
    }
    // key = value
    const std::size_t eq = line.find('=');
    if (eq == std::string_view::npos || section == Section::None) {
      fail(i, "expected 'key = value' inside a header or spline section", std::string(line));
    }
    const std::string key = lower(trim(line.substr(0, eq)));
    const std::string_view value = trim(line.substr(eq + 1));
    auto number = [&]() {
      const auto v = parse_fortran_real(value);
      if (!v) fail(i, fmt::format("expected a number for '{}'", key), std::string(value));
      return *v;
    };
    if (section == Section::Header) {
      if (key == "type") {
        const double type = number();
        const double want = is_wheel ? 1.0 : 0.0;
        if (type != want) {
          fail(i,
               fmt::format("SIMPACK profile type {} does not match the file use ({} expects type "
                           "{})",
                           type, is_wheel ? "wheel .prw" : "rail .prr", want));
        }
      } else if (key != "version") {
        warnings.push_back(fmt::format("{}:{}: unknown header key '{}' ignored", file, i + 1, key));
      }
      continue;
    }
    if (key == "point.dist.min") {
      raw.min_spacing = std::max(number(), 1e-6);
    } else if (key == "shift.y") {
      raw.shift_y = number();
    } else if (key == "shift.z") {
      raw.shift_z = number();
    } else if (key == "rotate") {
      if (number() != 0.0)
        fail(i, "SIMPACK 'rotate' must be 0 (profile rotation is not supported)");
    } else if (key == "bound.y.min") {
      raw.bound_y_min = number();
    } else if (key == "bound.y.max") {
      raw.bound_y_max = number();
    } else if (key == "bound.z.min") {
      raw.bound_z_min = number();
    } else if (key == "bound.z.max") {
      raw.bound_z_max = number();
    } else if (key == "mirror.y") {
      raw.mirror_y_flag = number() != 0.0 ? 1 : 0;
    } else if (key == "mirror.z") {
      raw.mirror_z_flag = number() != 0.0 ? 1 : 0;
    } else if (key == "inversion") {
      raw.inversion = number() != 0.0 ? 1 : 0;
    } else if (key == "units.len.f") {
      const double f = number();
      if (!(f > 0.0)) fail(i, fmt::format("units.len.f = {} must be positive", f));
      raw.length_to_mm = 1000.0 / f;
    } else if (key == "units.ang.f" || key == "approx.smooth" || key == "file" ||
               key == "file.mtime" || key == "comment" || key == "type") {
      // informative only
    } else {
      warnings.push_back(fmt::format("{}:{}: unknown spline key '{}' ignored", file, i + 1, key));
    }
  }
  if (!header_seen && !spline_seen) {
    throw InputError(file, 0, "no 'header.begin' / 'spline.begin' section: not a SIMPACK profile");
  }
  if (!points_seen) fail(last_line, "no 'point.begin' section in the SIMPACK profile");
  if (!finished) fail(last_line, "end of file before 'spline.end'");
  if (raw.y.size() < 2) {
    fail(last_line, fmt::format("a profile needs at least 2 points, found {}", raw.y.size()));
  }
  return raw;
}

}  // namespace rollcontact::format
