#include "format/text/inp_lexer.hpp"

#include <cctype>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <system_error>

namespace rollcontact::format {

namespace {

bool is_separator(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == ',' || c == '=' || c == '\v' || c == '\f';
}

bool is_digit(char c) {
  return c >= '0' && c <= '9';
}

}  // namespace

std::string_view significant_text(std::string_view raw_line) {
  std::string_view text = raw_line.substr(0, kInpLineLength);
  bool in_quote = false;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] == '\'') in_quote = !in_quote;
    if (text[i] == '%' && !in_quote) return text.substr(0, i);
  }
  return text;
}

InpLineWords split_words(std::string_view text, std::size_t max_words) {
  InpLineWords out;
  std::size_t i = 0;
  while (i < text.size() && out.words.size() < max_words) {
    if (is_separator(text[i])) {
      ++i;
      continue;
    }
    InpWord word;
    if (text[i] == '\'') {
      const std::size_t close = text.find('\'', i + 1);
      if (close == std::string_view::npos) {
        out.unterminated_quote = true;
        std::string_view rest = text.substr(i);
        while (!rest.empty() && is_separator(rest.back())) rest.remove_suffix(1);
        word.text = std::string(rest);
        word.quoted = true;
        out.words.push_back(std::move(word));
        return out;
      }
      word.text = std::string(text.substr(i + 1, close - i - 1));
      word.quoted = true;
      i = close + 1;
    } else {
      const std::size_t start = i;
      while (i < text.size() && !is_separator(text[i])) ++i;
      word.text = std::string(text.substr(start, i - start));
    }
    out.words.push_back(std::move(word));
  }
  return out;
}

std::optional<int> parse_fortran_integer(std::string_view word) {
  if (word.empty()) return std::nullopt;
  std::size_t i = 0;
  bool negative = false;
  if (word[0] == '+' || word[0] == '-') {
    negative = word[0] == '-';
    i = 1;
  }
  if (i == word.size()) return std::nullopt;
  long long value = 0;
  for (; i < word.size(); ++i) {
    if (!is_digit(word[i])) return std::nullopt;
    value = value * 10 + (word[i] - '0');
    if (value > static_cast<long long>(INT_MAX) + 1) return std::nullopt;
  }
  if (negative) value = -value;
  if (value > INT_MAX || value < INT_MIN) return std::nullopt;
  return static_cast<int>(value);
}

std::optional<int> parse_integer_field(std::string_view word) {
  if (const auto v = parse_fortran_integer(word)) return v;
  const auto r = parse_fortran_real(word);
  if (!r || *r != std::round(*r) || *r > INT_MAX || *r < INT_MIN) return std::nullopt;
  return static_cast<int>(*r);
}

std::optional<double> parse_fortran_real(std::string_view word) {
  // Validate the grammar ourselves (from_chars would also accept inf/nan/hex forms), then
  // normalise the Fortran exponent letters to 'e' for the conversion.
  std::string normalised;
  normalised.reserve(word.size());
  std::size_t i = 0;
  if (i < word.size() && (word[i] == '+' || word[i] == '-')) {
    if (word[i] == '-') normalised.push_back('-');
    ++i;
  }
  std::size_t mantissa_digits = 0;
  while (i < word.size() && is_digit(word[i])) {
    normalised.push_back(word[i++]);
    ++mantissa_digits;
  }
  if (i < word.size() && word[i] == '.') {
    normalised.push_back(word[i++]);
    while (i < word.size() && is_digit(word[i])) {
      normalised.push_back(word[i++]);
      ++mantissa_digits;
    }
  }
  if (mantissa_digits == 0) return std::nullopt;
  if (i < word.size()) {
    const char e = static_cast<char>(std::tolower(static_cast<unsigned char>(word[i])));
    // Fortran also reads an exponent written without its letter when it is signed: `.1-07`,
    // `1.5+03` (a mantissa followed directly by the signed exponent).
    const bool signed_exponent = e == '+' || e == '-';
    if (e != 'e' && e != 'd' && e != 'q' && !signed_exponent) return std::nullopt;
    normalised.push_back('e');
    if (!signed_exponent) ++i;
    if (i < word.size() && (word[i] == '+' || word[i] == '-')) normalised.push_back(word[i++]);
    std::size_t exponent_digits = 0;
    while (i < word.size() && is_digit(word[i])) {
      normalised.push_back(word[i++]);
      ++exponent_digits;
    }
    if (exponent_digits == 0 || i != word.size()) return std::nullopt;
  }
  double value = 0.0;
  const char* first = normalised.data();
  const char* last = first + normalised.size();
  const auto [ptr, ec] = std::from_chars(first, last, value);
  if (ec == std::errc::result_out_of_range && ptr == last) {
    // Underflow (1e-400) reads as zero or a subnormal, as Fortran's READ gives it; overflow
    // (1e999) has no finite value and stays an error. strtod tells the two apart (the C locale
    // is never changed by rollcontact, so '.' is its decimal point).
    const double v = std::strtod(normalised.c_str(), nullptr);
    if (std::isfinite(v)) return v;
    return std::nullopt;
  }
  if (ec != std::errc{} || ptr != last) return std::nullopt;
  return value;
}

std::optional<double> parse_angle(std::string_view word) {
  if (word.empty()) return std::nullopt;
  const char suffix = word.back();
  if (suffix == 'd' || suffix == 'D') {
    const auto degrees = parse_fortran_real(word.substr(0, word.size() - 1));
    if (!degrees) return std::nullopt;
    return *degrees * std::numbers::pi / 180.0;
  }
  if (suffix == 'r' || suffix == 'R') return parse_fortran_real(word.substr(0, word.size() - 1));
  return parse_fortran_real(word);
}

std::optional<bool> parse_logical(std::string_view word) {
  std::string w;
  for (const char c : word)
    w.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
  if (w.size() >= 2 && w.front() == '.' && w.back() == '.') w = w.substr(1, w.size() - 2);
  if (w == "T" || w == "TRUE") return true;
  if (w == "F" || w == "FALSE") return false;
  return std::nullopt;
}

}  // namespace rollcontact::format
