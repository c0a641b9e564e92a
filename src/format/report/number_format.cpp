#include "format/report/number_format.hpp"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <string_view>

namespace rollcontact::format {
namespace {

// Fortran fills a field that is too narrow with asterisks instead of widening it; readers of
// CONTACT reports rely on fixed columns, so we do the same.
std::string fit(std::string s, int width) {
  const auto w = static_cast<std::size_t>(width);
  if (s.size() > w) return std::string(w, '*');
  return std::string(w - s.size(), ' ') + s;
}

// Decimal exponent of |v| after rounding to `digits` significant digits (v != 0), and the
// rounded digits themselves (without the decimal point).
struct Rounded {
  std::string digits;
  int exponent = 0;  ///< v ≈ d.ddd × 10^exponent
};

Rounded round_significant(double v, int digits) {
  const std::string s = fmt::format("{:.{}E}", std::fabs(v), digits - 1);
  Rounded r;
  const auto epos = s.find('E');
  r.digits.push_back(s[0]);
  if (digits > 1) r.digits += s.substr(2, epos - 2);
  r.exponent = std::atoi(s.c_str() + epos + 1);
  return r;
}

}  // namespace

double filter_small(double v, double threshold) {
  return std::fabs(v) < threshold ? 0.0 : v;
}

std::string fmt_sig(int width, int digits, int sci_digits, double v) {
  const double a = std::fabs(v);
  const int lg = a < 1e-20 ? 0 : static_cast<int>(std::floor(std::log10(a) + 1e-7));
  std::string s;
  if (lg >= digits || lg <= -2) {
    s = fmt::format("{:.{}E}", v, sci_digits - 1);
  } else {
    const int decimals = std::max(0, digits - lg - 1);
    s = fmt::format("{:.{}f}", v, decimals);
    if (decimals == 0) s += '.';
  }
  return fit(std::move(s), width);
}

std::string fortran_f(double v, int width, int decimals) {
  std::string s = fmt::format("{:.{}f}", v, decimals);
  if (decimals == 0) s += '.';
  // Fortran's leading zero before the decimal point is optional: it goes first when space is short.
  if (s.size() > static_cast<std::size_t>(width)) {
    if (s.rfind("0.", 0) == 0) {
      s.erase(0, 1);
    } else if (s.rfind("-0.", 0) == 0) {
      s.erase(1, 1);
    }
  }
  return fit(std::move(s), width);
}

std::string fortran_e(double v, int width, int decimals) {
  const int d = std::max(1, decimals);
  std::string mantissa;
  int exponent = 0;
  if (v == 0.0) {
    mantissa = std::string(static_cast<std::size_t>(d), '0');
  } else {
    const Rounded r = round_significant(v, d);
    mantissa = r.digits;
    exponent = r.exponent + 1;  // 0.ddd × 10^(e+1)
  }
  const char sign = exponent < 0 ? '-' : '+';
  const int ae = std::abs(exponent);
  const std::string exp_part =
      ae <= 99 ? fmt::format("E{}{:02d}", sign, ae) : fmt::format("{}{:03d}", sign, ae);
  const std::string neg = std::signbit(v) ? "-" : "";
  std::string s = neg + "0." + mantissa + exp_part;
  if (s.size() > static_cast<std::size_t>(width)) s = neg + "." + mantissa + exp_part;
  return fit(std::move(s), width);
}

std::string fortran_g(double v, int width, int decimals) {
  constexpr int blanks = 4;  // room of the "E+dd" part that the fixed form leaves empty
  const std::string tail(blanks, ' ');
  if (v == 0.0) return fortran_f(v, width - blanks, decimals - 1) + tail;
  if (!std::isfinite(v)) return fit(fmt::format("{}", v), width);
  const int s = round_significant(v, decimals).exponent + 1;
  if (s >= 0 && s <= decimals) return fortran_f(v, width - blanks, decimals - s) + tail;
  return fortran_e(v, width, decimals);
}

std::string fortran_i(long long v, int width) {
  return fit(fmt::format("{}", v), width);
}

}  // namespace rollcontact::format
