#pragma once
// Lexical layer of CONTACT's .inp language (spec/inp-format.md §1): line truncation, `%`
// comments, word separators, quoted strings and the Fortran list-directed number forms.
// Pure functions on strings: no I/O, no state.

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rollcontact::format {

/// Characters of a line that are significant (the rest is ignored, as in CONTACT's 256-char
/// buffer).
inline constexpr std::size_t kInpLineLength = 256;
/// Words of a line examined when reading a group of typed values.
inline constexpr std::size_t kGroupWordLimit = 20;
/// Words of a line examined when filling an array.
inline constexpr std::size_t kArrayWordLimit = 50;

/// One word of an input line. Quoted strings are returned without their quotes.
struct InpWord {
  std::string text;
  bool quoted = false;
};

/// The words of one line and whether a quote was left open.
struct InpLineWords {
  std::vector<InpWord> words;
  bool unterminated_quote = false;
};

/// The significant part of a raw line: its first 256 characters with the comment removed. A `%`
/// inside a quoted string does not start a comment (file names may contain it).
std::string_view significant_text(std::string_view raw_line);

/// Splits significant text into at most `max_words` words. Blanks, TABs, carriage returns, commas
/// and `=` separate words; a quoted string ('...') is one word and may contain separators.
InpLineWords split_words(std::string_view text, std::size_t max_words);

/// Fortran list-directed integer: optional sign and decimal digits only (leading zeros allowed,
/// `022020` = 22020). Words with a decimal point or exponent, or out of `int` range, give nullopt.
std::optional<int> parse_fortran_integer(std::string_view word);

/// An integer field as CONTACT reads it: a Fortran integer, or a real with an integral value
/// (`1.0`, `2.`, `1e1`); `19.5` and values out of `int` range give nullopt.
std::optional<int> parse_integer_field(std::string_view word);

/// Real in any usual form: `0.35`, `.13333`, `82000.`, `3.5E-1`, `1d-5`, `-0.0009999`, `10000`.
/// `d`/`D` (and `q`/`Q`) are accepted as exponent letters, and a signed exponent may follow the
/// mantissa directly (`.1-07`, `1.5+03`), as Fortran reads it. inf/nan and trailing text give
/// nullopt.
std::optional<double> parse_fortran_real(std::string_view word);

/// Angle: a real with optional suffix `d`/`D` (degrees, converted) or `r`/`R` (radians, as is).
/// Returns radians.
std::optional<double> parse_angle(std::string_view word);

/// Logical: `T`/`t` or `F`/`f` (also `.TRUE.`/`.FALSE.` forms).
std::optional<bool> parse_logical(std::string_view word);

}  // namespace rollcontact::format
