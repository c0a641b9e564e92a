#include "format/report/number_format.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string_view>
#include <utility>

namespace rollcontact::format {
namespace {

// Report and .mat files hold up to millions of numbers: each is built in a fixed buffer, with
// one string (or none, when appended) per number instead of one per formatting step.
class Text {
 public:
  template <class... T>
  void format(fmt::format_string<T...> f, T&&... args) {
    const auto r = fmt::format_to_n(c_ + n_, capacity - n_, f, std::forward<T>(args)...);
    n_ += std::min(r.size, capacity - n_);
  }
  /// v with `precision` digits after the point, in the C locale's %.*f or %.*E form
  /// (std::to_chars: the same digits as printf, without parsing a format string).
  void put_number(double v, std::chars_format form, int precision) {
    const auto r = std::to_chars(c_ + n_, c_ + capacity, v, form, precision);
    if (r.ec != std::errc()) return;
    const std::size_t start = n_;
    n_ = static_cast<std::size_t>(r.ptr - c_);
    if (form == std::chars_format::scientific)
      for (std::size_t k = start; k < n_; ++k)
        if (c_[k] == 'e') c_[k] = 'E';
  }
  void put(std::string_view s) {
    const std::size_t k = std::min(s.size(), capacity - n_);
    std::copy_n(s.data(), k, c_ + n_);
    n_ += k;
  }
  void put(char ch) {
    if (n_ < capacity) c_[n_++] = ch;
  }
  void erase(std::size_t pos) {  // removes one character
    std::copy(c_ + pos + 1, c_ + n_, c_ + pos);
    --n_;
  }
  bool starts_with(std::string_view s) const { return view().substr(0, s.size()) == s; }
  std::size_t size() const noexcept { return n_; }
  std::string_view view() const noexcept { return {c_, n_}; }

 private:
  static constexpr std::size_t capacity = 64;
  char c_[capacity];
  std::size_t n_ = 0;
};

// Fortran fills a field that is too narrow with asterisks instead of widening it; readers of
// CONTACT reports rely on fixed columns, so we do the same.
void append_fit(std::string& out, const Text& t, int width) {
  const auto w = static_cast<std::size_t>(width);
  if (t.size() > w) {
    out.append(w, '*');
    return;
  }
  out.append(w - t.size(), ' ');
  out.append(t.view());
}

std::string fit(const Text& t, int width) {
  std::string s;
  append_fit(s, t, width);
  return s;
}

// Decimal exponent of |v| after rounding to `digits` significant digits (v != 0), and the
// rounded digits themselves (without the decimal point).
struct Rounded {
  Text digits;
  int exponent = 0;  ///< v ≈ d.ddd × 10^exponent
};

Rounded round_significant(double v, int digits) {
  Text t;
  t.put_number(std::fabs(v), std::chars_format::scientific, digits - 1);
  const std::string_view s = t.view();
  Rounded r;
  const auto epos = s.find('E');
  r.digits.put(s[0]);
  if (digits > 1) r.digits.put(s.substr(2, epos - 2));
  int e = 0;
  std::from_chars(s.data() + epos + (s[epos + 1] == '+' ? 2 : 1), s.data() + s.size(), e);
  r.exponent = e;
  return r;
}

Text fixed(double v, int width, int decimals) {
  Text t;
  t.put_number(v, std::chars_format::fixed, decimals);
  if (decimals == 0) t.put('.');
  // Fortran's leading zero before the decimal point is optional: it goes first when space is short.
  if (t.size() > static_cast<std::size_t>(width)) {
    if (t.starts_with("0.")) {
      t.erase(0);
    } else if (t.starts_with("-0.")) {
      t.erase(1);
    }
  }
  return t;
}

Text exponential(double v, int width, int decimals) {
  const int d = std::max(1, decimals);
  Text mantissa;
  int exponent = 0;
  if (v == 0.0) {
    for (int k = 0; k < d; ++k) mantissa.put('0');
  } else {
    const Rounded r = round_significant(v, d);
    mantissa = r.digits;
    exponent = r.exponent + 1;  // 0.ddd × 10^(e+1)
  }
  const char sign = exponent < 0 ? '-' : '+';
  const int ae = std::abs(exponent);
  const bool negative = std::signbit(v);
  const std::size_t length = (negative ? 1 : 0) + 2 + mantissa.size() + 4;
  Text t;
  if (negative) t.put('-');
  if (length <= static_cast<std::size_t>(width)) t.put('0');
  t.put('.');
  t.put(mantissa.view());
  if (ae <= 99) t.put('E');
  t.put(sign);
  if (ae > 99) t.put(static_cast<char>('0' + ae / 100 % 10));
  t.put(static_cast<char>('0' + ae / 10 % 10));
  t.put(static_cast<char>('0' + ae % 10));
  return t;
}

void append_g(std::string& out, double v, int width, int decimals) {
  constexpr int blanks = 4;  // room of the "E+dd" part that the fixed form leaves empty
  if (v == 0.0) {
    append_fit(out, fixed(v, width - blanks, decimals - 1), width - blanks);
    out.append(blanks, ' ');
    return;
  }
  if (!std::isfinite(v)) {
    Text t;
    t.format("{}", v);
    append_fit(out, t, width);
    return;
  }
  const int s = round_significant(v, decimals).exponent + 1;
  if (s >= 0 && s <= decimals) {
    append_fit(out, fixed(v, width - blanks, decimals - s), width - blanks);
    out.append(blanks, ' ');
    return;
  }
  append_fit(out, exponential(v, width, decimals), width);
}

}  // namespace

double filter_small(double v, double threshold) {
  return std::fabs(v) < threshold ? 0.0 : v;
}

void append_fmt_sig(std::string& out, int width, int digits, int sci_digits, double v) {
  if (v == 0.0) v = 0.0;  // a zero mirrored for the left wheel (−0) prints as 0, as CONTACT's
  const double a = std::fabs(v);
  const int lg = a < 1e-20 ? 0 : static_cast<int>(std::floor(std::log10(a) + 1e-7));
  Text t;
  if (lg >= digits || lg <= -2) {
    t.put_number(v, std::chars_format::scientific, sci_digits - 1);
  } else {
    const int decimals = std::max(0, digits - lg - 1);
    t.put_number(v, std::chars_format::fixed, decimals);
    if (decimals == 0) t.put('.');
  }
  append_fit(out, t, width);
}

std::string fmt_sig(int width, int digits, int sci_digits, double v) {
  std::string s;
  append_fmt_sig(s, width, digits, sci_digits, v);
  return s;
}

std::string fortran_f(double v, int width, int decimals) {
  return fit(fixed(v, width, decimals), width);
}

std::string fortran_e(double v, int width, int decimals) {
  return fit(exponential(v, width, decimals), width);
}

std::string fortran_g(double v, int width, int decimals) {
  std::string s;
  append_g(s, v, width, decimals);
  return s;
}

void append_fortran_g(std::string& out, double v, int width, int decimals) {
  append_g(out, v, width, decimals);
}

std::string fortran_i(long long v, int width) {
  Text t;
  t.format("{}", v);
  return fit(t, width);
}

}  // namespace rollcontact::format
