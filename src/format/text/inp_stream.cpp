#include "format/text/inp_stream.hpp"

#include <algorithm>
#include <optional>
#include <utility>

#include "format/text/inp_lexer.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

/// Values reserved before an array is read; more as they come.
constexpr std::size_t kInitialReserve = 4096;

std::string_view kind_name(FieldKind kind) {
  switch (kind) {
    case FieldKind::integer:
    case FieldKind::digits:
      return "an integer";
    case FieldKind::real:
      return "a real number";
    case FieldKind::angle:
      return "an angle";
    case FieldKind::string:
      return "a quoted string";
    case FieldKind::logical:
      return "a logical (T or F)";
  }
  return "a value";
}

/// Parses one word into `item`; false if it does not have the field's type.
bool parse_into(const InpWord& word, FieldKind kind, GroupValues::Item& item) {
  switch (kind) {
    case FieldKind::integer:
    case FieldKind::digits: {
      if (word.quoted) return false;
      const auto v = kind == FieldKind::digits ? parse_fortran_integer(word.text)
                                               : parse_integer_field(word.text);
      if (!v) return false;
      item.integer = *v;
      item.real = *v;
      return true;
    }
    case FieldKind::real:
    case FieldKind::angle: {
      if (word.quoted) return false;
      const auto v =
          kind == FieldKind::real ? parse_fortran_real(word.text) : parse_angle(word.text);
      if (!v) return false;
      item.real = *v;
      return true;
    }
    case FieldKind::string:
      // Fortran list-directed input also takes an unquoted word as a string.
      item.text = word.text;
      return !word.text.empty();
    case FieldKind::logical: {
      if (word.quoted) return false;
      const auto v = parse_logical(word.text);
      if (!v) return false;
      item.logical = *v;
      return true;
    }
  }
  return false;
}

}  // namespace

namespace {

/// A UTF-8 byte-order mark (editors on Windows write one): not part of the input.
constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

/// Column (1-based) of the first character past CONTACT's 256 that would be lost: text beyond
/// column 256 that is neither blank nor inside a comment begun before it. 0 when nothing is lost.
std::size_t lost_text_column(std::string_view line) {
  if (line.size() <= kInpLineLength) return 0;
  const std::string_view kept = line.substr(0, kInpLineLength);
  if (significant_text(kept).size() < kept.size()) return 0;  // a comment runs past the limit
  const std::size_t k = line.find_first_not_of(" \t\r", kInpLineLength);
  if (k == std::string_view::npos || line[k] == '%') return 0;  // blanks, or a comment
  return k + 1;
}

}  // namespace

InpStream::InpStream(std::string_view text, std::string file_name) : file_(std::move(file_name)) {
  if (text.starts_with(kByteOrderMark)) text.remove_prefix(kByteOrderMark.size());
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) {
      lines_.emplace_back(text.substr(start));
      break;
    }
    lines_.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  // CONTACT reads 256 characters of a line; text after them would vanish without a trace and
  // shift every value that follows, so it is an error here, at its line and column.
  for (std::size_t i = 0; i < lines_.size(); ++i)
    if (const std::size_t column = lost_text_column(lines_[i]); column > 0) {
      fail(static_cast<int>(i) + 1,
           "text from column " + std::to_string(column) +
               " would be ignored: CONTACT reads only the first 256 characters of a line (split "
               "the values over two lines, or start a comment with %)",
           lines_[i].substr(column - 1, 20));
    }
}

void InpStream::fail(int line, std::string message, std::string offending) const {
  // A group that took values from a later line, shortly before the error: the likely cause is
  // a value missing on its first line, which shifted everything after it.
  if (spanned_.first_line > 0 && spanned_.first_line < line &&
      line <= spanned_.last_line + kSpannedHintLines) {
    message += "; note: " + spanned_.what + " on line " + std::to_string(spanned_.first_line) +
               " took values from line " + std::to_string(spanned_.last_line) +
               " — is a value missing on line " + std::to_string(spanned_.first_line) + "?";
  }
  throw InputError(file_, line, std::move(message), std::move(offending));
}

bool InpStream::skip_to_content() {
  while (next_ < lines_.size()) {
    const auto words = split_words(significant_text(lines_[next_]), 1);
    if (!words.words.empty()) return true;
    ++next_;
  }
  return false;
}

bool InpStream::at_end() {
  return !skip_to_content();
}

int InpStream::next_line() {
  if (skip_to_content()) return static_cast<int>(next_) + 1;
  return line_count();
}

GroupValues InpStream::read_group(std::initializer_list<FieldSpec> fields, std::string_view what) {
  const std::vector<FieldSpec> spec(fields);
  std::size_t n_mandatory = 0;
  while (n_mandatory < spec.size() && !spec[n_mandatory].optional) ++n_mandatory;
  std::vector<GroupValues::Item> items(spec.size());

  std::size_t field = 0;
  int first_line = 0;
  while (field < n_mandatory) {
    if (!skip_to_content()) {
      fail(line_count(), "end of file while reading " + std::string(what) + " (" +
                             std::string(spec[field].name) + " missing)");
    }
    const int line = static_cast<int>(next_) + 1;
    const auto split = split_words(significant_text(lines_[next_]), kGroupWordLimit);
    ++next_;
    last_line_ = line;
    if (first_line == 0) first_line = line;
    if (split.unterminated_quote) {
      fail(line, "unterminated quoted string in " + std::string(what), split.words.back().text);
    }
    std::size_t w = 0;
    for (; w < split.words.size() && field < n_mandatory; ++w, ++field) {
      auto& item = items[field];
      if (!parse_into(split.words[w], spec[field].kind, item)) {
        fail(line,
             "expected " + std::string(kind_name(spec[field].kind)) + " for " +
                 std::string(spec[field].name) + " in " + std::string(what),
             split.words[w].text);
      }
      item.present = true;
      item.line = line;
    }
    if (field == n_mandatory) {
      // Optional values only from the line of the last mandatory value; the first word that
      // does not parse (typically a trailing label) ends the line.
      for (; field < spec.size() && w < split.words.size(); ++field, ++w) {
        auto& item = items[field];
        if (!parse_into(split.words[w], spec[field].kind, item)) break;
        item.present = true;
        item.line = line;
      }
      for (auto& item : items) {
        if (!item.present) item.line = line;
      }
    }
  }
  // The earliest span within the hint window is the one a shifted value starts from.
  if (last_line_ > first_line &&
      (spanned_.first_line == 0 || first_line > spanned_.last_line + kSpannedHintLines))
    spanned_ = {first_line, last_line_, std::string(what)};
  return GroupValues(std::move(items));
}

template <typename Parse>
void InpStream::fill_array(std::size_t n, std::string_view what, std::string_view kind,
                           Parse parse) {
  std::size_t k = 0;
  while (k < n) {
    if (!skip_to_content()) {
      fail(line_count(), "end of file while reading " + std::string(what) + " (" +
                             std::to_string(k) + " of " + std::to_string(n) + " values read)");
    }
    const int line = static_cast<int>(next_) + 1;
    const auto split = split_words(significant_text(lines_[next_]), kArrayWordLimit + 1);
    ++next_;
    last_line_ = line;
    const std::size_t used = std::min(split.words.size(), kArrayWordLimit);
    for (std::size_t w = 0; w < used && k < n; ++w, ++k) {
      if (split.words[w].quoted || !parse(k, split.words[w].text)) {
        fail(line,
             "expected " + std::string(kind) + " for value " + std::to_string(k + 1) + " of " +
                 std::string(what),
             split.words[w].text);
      }
    }
    // CONTACT reads at most 50 words of an array line: values beyond would be lost silently.
    if (split.words.size() > kArrayWordLimit && k < n) {
      fail(line,
           "more than " + std::to_string(kArrayWordLimit) + " values on one line of " +
               std::string(what) + ": CONTACT reads " + std::to_string(kArrayWordLimit) +
               " per line and would lose the rest; continue on the next line",
           split.words[kArrayWordLimit].text);
    }
  }
}

std::vector<double> InpStream::read_reals(std::size_t n, std::string_view what,
                                          const std::function<bool(std::size_t)>& is_angle) {
  // Grown as values arrive: a short file that announces two million values costs nothing.
  std::vector<double> values;
  values.reserve(std::min<std::size_t>(n, kInitialReserve));
  fill_array(n, what, "a real number", [&](std::size_t k, const std::string& word) {
    const auto v = (is_angle && is_angle(k)) ? parse_angle(word) : parse_fortran_real(word);
    if (!v) return false;
    values.push_back(*v);
    return true;
  });
  return values;
}

std::vector<int> InpStream::read_integers(std::size_t n, std::string_view what) {
  std::vector<int> values;
  values.reserve(std::min<std::size_t>(n, kInitialReserve));
  fill_array(n, what, "an integer", [&](std::size_t, const std::string& word) {
    const auto v = parse_integer_field(word);
    if (!v) return false;
    values.push_back(*v);
    return true;
  });
  return values;
}

}  // namespace rollcontact::format
