#pragma once
// Line handling shared by the profile file readers (spec/inp-format.md §8.1, §8.2, §8.4):
// splitting a file into lines, removing comments that start with one of several characters
// outside single quotes, and reading a whole file with an InputError when it cannot be opened.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rollcontact::format {

/// The lines of a text (without line terminators; a trailing CR is removed).
std::vector<std::string> split_lines(std::string_view text);

/// `line` up to the first character of `comment_chars` that is not inside single quotes.
std::string_view strip_comment(std::string_view line, std::string_view comment_chars);

/// `s` without leading and trailing blanks, TABs and CRs.
std::string_view trim(std::string_view s);

/// Numbers of a data line separated by blanks, TABs, commas or semicolons; false when a word is
/// not a real number (`bad` then holds it).
bool parse_number_row(std::string_view line, std::vector<double>& values, std::string& bad);

/// Whole content of a file. Throws InputError(file, 0, ...) when it cannot be read.
std::string read_text_file(const std::filesystem::path& path);

}  // namespace rollcontact::format
