#include "format/profiles/profile_text.hpp"

#include <fstream>
#include <sstream>

#include "format/text/inp_lexer.hpp"
#include "format/text/input_file.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {

std::vector<std::string> split_lines(std::string_view text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string_view::npos) end = text.size();
    std::string_view line = text.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    lines.emplace_back(line);
    start = end + 1;
  }
  return lines;
}

std::string_view strip_comment(std::string_view line, std::string_view comment_chars) {
  bool in_quote = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '\'') in_quote = !in_quote;
    if (!in_quote && comment_chars.find(line[i]) != std::string_view::npos) {
      return line.substr(0, i);
    }
  }
  return line;
}

std::string_view trim(std::string_view s) {
  constexpr std::string_view kBlank = " \t\r";
  const std::size_t first = s.find_first_not_of(kBlank);
  if (first == std::string_view::npos) return {};
  const std::size_t last = s.find_last_not_of(kBlank);
  return s.substr(first, last - first + 1);
}

bool parse_number_row(std::string_view line, std::vector<double>& values, std::string& bad) {
  constexpr std::string_view kSeparators = " \t\r,;";
  values.clear();
  std::size_t i = 0;
  while (i < line.size()) {
    if (kSeparators.find(line[i]) != std::string_view::npos) {
      ++i;
      continue;
    }
    std::size_t end = line.find_first_of(kSeparators, i);
    if (end == std::string_view::npos) end = line.size();
    const std::string_view word = line.substr(i, end - i);
    const auto v = parse_fortran_real(word);
    if (!v) {
      bad = std::string(word);
      return false;
    }
    values.push_back(*v);
    i = end;
  }
  return true;
}

std::string read_text_file(const std::filesystem::path& path) {
  return read_input_file(path, "profile file");
}

}  // namespace rollcontact::format
