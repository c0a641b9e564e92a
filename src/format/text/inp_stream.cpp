#include "format/text/inp_stream.hpp"

#include <optional>
#include <utility>

#include "format/text/inp_lexer.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

namespace {

std::string_view kind_name(FieldKind kind) {
  switch (kind) {
    case FieldKind::integer:
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
    case FieldKind::integer: {
      if (word.quoted) return false;
      const auto v = parse_fortran_integer(word.text);
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

InpStream::InpStream(std::string_view text, std::string file_name) : file_(std::move(file_name)) {
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
}

void InpStream::fail(int line, std::string message, std::string offending) const {
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
  while (field < n_mandatory) {
    if (!skip_to_content()) {
      fail(line_count(), "end of file while reading " + std::string(what) + " (" +
                             std::string(spec[field].name) + " missing)");
    }
    const int line = static_cast<int>(next_) + 1;
    const auto split = split_words(significant_text(lines_[next_]), kGroupWordLimit);
    ++next_;
    last_line_ = line;
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
    const auto split = split_words(significant_text(lines_[next_]), kArrayWordLimit);
    ++next_;
    last_line_ = line;
    for (std::size_t w = 0; w < split.words.size() && k < n; ++w, ++k) {
      if (split.words[w].quoted || !parse(k, split.words[w].text)) {
        fail(line,
             "expected " + std::string(kind) + " for value " + std::to_string(k + 1) + " of " +
                 std::string(what),
             split.words[w].text);
      }
    }
  }
}

std::vector<double> InpStream::read_reals(std::size_t n, std::string_view what,
                                          const std::function<bool(std::size_t)>& is_angle) {
  std::vector<double> values(n);
  fill_array(n, what, "a real number", [&](std::size_t k, const std::string& word) {
    const auto v = (is_angle && is_angle(k)) ? parse_angle(word) : parse_fortran_real(word);
    if (!v) return false;
    values[k] = *v;
    return true;
  });
  return values;
}

std::vector<int> InpStream::read_integers(std::size_t n, std::string_view what) {
  std::vector<int> values(n);
  fill_array(n, what, "an integer", [&](std::size_t k, const std::string& word) {
    const auto v = parse_fortran_integer(word);
    if (!v) return false;
    values[k] = *v;
    return true;
  });
  return values;
}

}  // namespace rollcontact::format
