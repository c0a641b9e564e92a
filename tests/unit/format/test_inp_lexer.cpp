// Lexical rules of the .inp language (spec/inp-format.md §1 and the §9 checklist) and the group /
// array reading rules of InpStream.

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "format/text/inp_lexer.hpp"
#include "format/text/inp_stream.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {
namespace {

std::vector<std::string> words(std::string_view line, std::size_t max = kGroupWordLimit) {
  std::vector<std::string> out;
  for (const auto& w : split_words(significant_text(line), max).words) out.push_back(w.text);
  return out;
}

using Strings = std::vector<std::string>;
constexpr double kPi = std::numbers::pi;

// ---- comments ----

TEST(InpLexer, ControlBytesOfABadValueAreShownEscaped) {
  // A binary file's bytes (NUL, escape) never reach the terminal raw: \xNN in the message.
  InpStream in(std::string(" 1 x\0\x1b[2J\n", 11), "bin.inp");
  try {
    (void)in.read_reals(2, "list");
    FAIL() << "a binary word was read as a number";
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'x\\x00\\x1B[2J'"), std::string::npos) << m;
    EXPECT_EQ(m.find('\0'), std::string::npos);
    EXPECT_EQ(m.find('\x1b'), std::string::npos);
  }
}

TEST(InpLexer, PercentStartsACommentToEndOfLine) {
  EXPECT_EQ(significant_text("  12  34 % FN, CKSI"), "  12  34 ");
  EXPECT_EQ(words("% whole line"), Strings{});
  EXPECT_EQ(words("    3   module  % Stage k=1"), (Strings{"3", "module"}));
  EXPECT_EQ(words("%%%%%%%%%%%%"), Strings{});
}

TEST(InpLexer, PercentInsideQuotesIsNotAComment) {
  EXPECT_EQ(words("'a%b.txt'  % comment"), (Strings{"a%b.txt"}));
}

TEST(InpLexer, EmptyAndSeparatorOnlyLinesHaveNoWords) {
  EXPECT_EQ(words(""), Strings{});
  EXPECT_EQ(words("   \t  "), Strings{});
  EXPECT_EQ(words(" , , = "), Strings{});
}

// ---- line length ----

TEST(InpLexer, OnlyThe256FirstCharactersAreSignificant) {
  std::string line(250, ' ');
  line += "12345678";  // columns 251..258: "123456" survives, "78" is cut
  line += " 99";
  EXPECT_EQ(significant_text(line).size(), kInpLineLength);
  EXPECT_EQ(words(line), (Strings{"123456"}));
}

// ---- separators ----

TEST(InpLexer, BlanksTabsCommasAndEqualsSeparateWords) {
  EXPECT_EQ(words("MAXGS , MAXIN"), (Strings{"MAXGS", "MAXIN"}));
  EXPECT_EQ(words("IXL,INC,IXH,"), (Strings{"IXL", "INC", "IXH"}));
  EXPECT_EQ(words("a=b = c"), (Strings{"a", "b", "c"}));
  EXPECT_EQ(words("1\t2\t\t3"), (Strings{"1", "2", "3"}));
  EXPECT_EQ(words("1 2\r"), (Strings{"1", "2"}));
  EXPECT_EQ(words("1,,2"), (Strings{"1", "2"}));
}

// ---- strings ----

TEST(InpLexer, QuotedStringsAreOneWordAndMayContainBlanks) {
  const auto split = split_words("  'MBench UIC60, v3.prr' 0 1.0", 20);
  ASSERT_EQ(split.words.size(), 3u);
  EXPECT_EQ(split.words[0].text, "MBench UIC60, v3.prr");
  EXPECT_TRUE(split.words[0].quoted);
  EXPECT_FALSE(split.words[1].quoted);
  EXPECT_FALSE(split.unterminated_quote);
}

TEST(InpLexer, UnterminatedQuoteIsFlagged) {
  const auto split = split_words("'abc.txt  ", 20);
  EXPECT_TRUE(split.unterminated_quote);
  ASSERT_EQ(split.words.size(), 1u);
  EXPECT_EQ(split.words[0].text, "'abc.txt");
}

// ---- word limits ----

TEST(InpLexer, WordLimitPerLine) {
  std::string line;
  for (int k = 1; k <= 60; ++k) line += std::to_string(k) + " ";
  EXPECT_EQ(words(line).size(), kGroupWordLimit);
  EXPECT_EQ(words(line, kArrayWordLimit).size(), kArrayWordLimit);
  EXPECT_EQ(words(line).back(), "20");
}

// ---- integers ----

TEST(InpLexer, FortranIntegersWithLeadingZeros) {
  EXPECT_EQ(parse_fortran_integer("022020"), 22020);
  EXPECT_EQ(parse_fortran_integer("0000331"), 331);
  EXPECT_EQ(parse_fortran_integer("10001541"), 10001541);
  EXPECT_EQ(parse_fortran_integer("2110"), 2110);
  EXPECT_EQ(parse_fortran_integer("-6"), -6);
  EXPECT_EQ(parse_fortran_integer("+7"), 7);
  EXPECT_EQ(parse_fortran_integer("0"), 0);
}

TEST(InpLexer, WordsThatAreNotIntegers) {
  for (const char* w :
       {"19.5", "1.", "1e3", "1d0", "", "-", "+", "12a", "MODULE", "0x10", "99999999999", "1,2"}) {
    EXPECT_FALSE(parse_fortran_integer(w).has_value()) << w;
  }
}

// ---- reals ----

TEST(InpLexer, RealsInAllUsualForms) {
  EXPECT_DOUBLE_EQ(*parse_fortran_real("0.35"), 0.35);
  EXPECT_DOUBLE_EQ(*parse_fortran_real(".13333"), 0.13333);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("82000."), 82000.0);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("3.5E-1"), 0.35);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1e-5"), 1e-5);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1d-5"), 1e-5);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1D+2"), 100.0);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("50e-3"), 0.05);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1.0E-06"), 1e-6);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("-0.0009999"), -0.0009999);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("10000"), 10000.0);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("+2.5"), 2.5);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("-.5"), -0.5);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("0000.5"), 0.5);
  // A signed exponent right after the mantissa, as Fortran (and CONTACT) reads it.
  EXPECT_DOUBLE_EQ(*parse_fortran_real(".1-07"), 1e-8);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1.5+03"), 1500.0);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("1-5"), 1e-5);
  EXPECT_DOUBLE_EQ(*parse_fortran_real("-2.5-1"), -0.25);
}

TEST(InpLexer, IntegerFieldsTakeIntegralReals) {
  EXPECT_EQ(parse_integer_field("1.0"), 1);
  EXPECT_EQ(parse_integer_field("2."), 2);
  EXPECT_EQ(parse_integer_field("1e1"), 10);
  EXPECT_EQ(parse_integer_field("-3.0D0"), -3);
  EXPECT_EQ(parse_integer_field("022020"), 22020);
  for (const char* w : {"19.5", "1e-1", "abc", "3e10", ""})
    EXPECT_FALSE(parse_integer_field(w).has_value()) << w;
}

TEST(InpLexer, WordsThatAreNotReals) {
  for (const char* w :
       {"",     ".",  "-",   "e5",      "1e",   "1e+", "1.2.3", "inf", "nan",  "NaN",
        "0x10", "1d", "90d", "3.1416r", "1e5x", "FN,", "abc",   "1-",  "1-5x", "1+-5"}) {
    EXPECT_FALSE(parse_fortran_real(w).has_value()) << w;
  }
}

// ---- angles ----

TEST(InpLexer, AnglesWithDegreeAndRadianSuffix) {
  EXPECT_DOUBLE_EQ(*parse_angle("90d"), kPi / 2);
  EXPECT_DOUBLE_EQ(*parse_angle("180.0d"), kPi);
  EXPECT_DOUBLE_EQ(*parse_angle("180.d"), kPi);
  EXPECT_DOUBLE_EQ(*parse_angle("180.0D"), kPi);
  EXPECT_DOUBLE_EQ(*parse_angle("-25.0d"), -25.0 * kPi / 180.0);
  EXPECT_DOUBLE_EQ(*parse_angle("-20d"), -20.0 * kPi / 180.0);
  EXPECT_DOUBLE_EQ(*parse_angle("3.1416r"), 3.1416);
  EXPECT_DOUBLE_EQ(*parse_angle("3.1416R"), 3.1416);
  EXPECT_DOUBLE_EQ(*parse_angle("0.5"), 0.5);
  EXPECT_DOUBLE_EQ(*parse_angle("1d-5"), 1e-5);  // exponent, not degrees
  EXPECT_DOUBLE_EQ(*parse_angle("1e1d"), 10.0 * kPi / 180.0);
  for (const char* w : {"d", "r", "xd", "90dd", "90 d", ""}) {
    EXPECT_FALSE(parse_angle(w).has_value()) << w;
  }
}

// ---- logicals ----

TEST(InpLexer, Logicals) {
  EXPECT_EQ(parse_logical("T"), true);
  EXPECT_EQ(parse_logical("t"), true);
  EXPECT_EQ(parse_logical("F"), false);
  EXPECT_EQ(parse_logical("f"), false);
  EXPECT_EQ(parse_logical(".TRUE."), true);
  EXPECT_EQ(parse_logical(".false."), false);
  EXPECT_FALSE(parse_logical("x").has_value());
  EXPECT_FALSE(parse_logical("Fish").has_value());
  EXPECT_FALSE(parse_logical("1").has_value());
}

// ---- group reading (InpStream) ----

constexpr FieldKind kI = FieldKind::integer;
constexpr FieldKind kR = FieldKind::real;

TEST(InpStreamGroups, GroupSpansLinesAndSkipsCommentsBetweenValues) {
  InpStream in("  1  2\n% a comment between the values\n\n  3.5 4.5  labels here\n  7\n", "t.inp");
  const GroupValues g =
      in.read_group({{"MX", kI}, {"MY", kI}, {"A", kR}, {"B", kR}, {"C", kR, true}}, "grp");
  EXPECT_EQ(g.integer(0), 1);
  EXPECT_EQ(g.integer(1), 2);
  EXPECT_DOUBLE_EQ(g.real(2), 3.5);
  EXPECT_DOUBLE_EQ(g.real(3), 4.5);
  EXPECT_FALSE(g.has(4));  // "labels" does not parse: dropped, ends the line
  EXPECT_EQ(g.line(0), 1);
  EXPECT_EQ(g.line(3), 4);
  EXPECT_EQ(in.last_line(), 4);
  // The next group starts on a fresh line.
  EXPECT_EQ(in.read_group({{"N", kI}}, "next").integer(0), 7);
  EXPECT_TRUE(in.at_end());
}

TEST(InpStreamGroups, OptionalValuesOnlyFromTheLineOfTheLastMandatoryValue) {
  InpStream in("022020\n3\n", "t.inp");
  const GroupValues g = in.read_group({{"W", kI}, {"M2", kI, true}}, "word 2");
  EXPECT_FALSE(g.has(1));
  EXPECT_EQ(in.read_group({{"X", kI}}, "x").integer(0), 3);

  InpStream in2("022020 12 garbage\n", "t.inp");
  const GroupValues g2 = in2.read_group({{"W", kI}, {"M2", kI, true}}, "word 2");
  EXPECT_EQ(g2.integer(1), 12);
}

TEST(InpStreamGroups, UnparsableOptionalWordEndsTheLine) {
  InpStream in(" 3 MODULE 5 7\n", "t.inp");
  const GroupValues g =
      in.read_group({{"MODULE", kI}, {"REID", kI, true}, {"CPID", kI, true}}, "module line");
  EXPECT_EQ(g.integer(0), 3);
  EXPECT_FALSE(g.has(1));
  EXPECT_FALSE(g.has(2));
}

TEST(InpStreamGroups, TrailingLabelsWithCommasAndEqualsAreIgnored) {
  InpStream in("   100   100    30     1   0.0001      MAXGS , MAXIN = 3\n", "t.inp");
  const GroupValues g = in.read_group(
      {{"MAXGS", kI}, {"MAXIN", kI}, {"MAXNR", kI}, {"MAXOUT", kI}, {"EPS", kR}, {"NP", kI, true}},
      "it");
  EXPECT_DOUBLE_EQ(g.real(4), 1e-4);
  EXPECT_FALSE(g.has(5));
}

TEST(InpStreamGroups, UnparsableMandatoryWordIsAnError) {
  InpStream in("\n\n   19.5   19  1 1 1 1\n", "cattaneo.inp");
  try {
    in.read_group({{"MX", kI}, {"MY", kI}}, "the IPOTCN=1 line");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.file(), "cattaneo.inp");
    EXPECT_EQ(e.offending(), "19.5");
    EXPECT_EQ(e.message(), "expected an integer for MX in the IPOTCN=1 line");
    EXPECT_EQ(std::string(e.what()),
              "cattaneo.inp:3: expected an integer for MX in the IPOTCN=1 line (found '19.5')");
  }
}

TEST(InpStreamGroups, EndOfFileWhileAMandatoryValueIsExpected) {
  InpStream in("1 2\n% trailing comment\n", "t.inp");
  try {
    in.read_group({{"A", kI}, {"B", kI}, {"C", kI}}, "the ABC line");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_NE(e.message().find("end of file while reading the ABC line (C missing)"),
              std::string::npos);
  }
}

TEST(InpStreamGroups, StringsQuotedOrNot) {
  InpStream in("  'inflcf r10.txt'   CFNAME\n plain.txt\n", "t.inp");
  EXPECT_EQ(in.read_group({{"CFNAME", FieldKind::string}}, "c9").text(0), "inflcf r10.txt");
  EXPECT_EQ(in.read_group({{"CFNAME", FieldKind::string}}, "c9").text(0), "plain.txt");
}

TEST(InpStreamGroups, AnglesOnlyInAngleFields) {
  InpStream in(" 180.d 0.1 30000.\n 90d\n", "t.inp");
  const GroupValues g =
      in.read_group({{"CHI", FieldKind::angle}, {"DQ", kR}, {"VELOC", kR}}, "rolling line");
  EXPECT_DOUBLE_EQ(g.real(0), kPi);
  EXPECT_THROW(in.read_group({{"DQ", kR}}, "x"), InputError);
}

// ---- arrays ----

TEST(InpStreamArrays, ArraysFillFromManyLinesWithCommentsBetween) {
  InpStream in(" 1 2 3\n% comment\n 4\n\n 5 6 7 8  rest is ignored\n 9\n", "t.inp");
  const auto v = in.read_reals(6, "B(1..6)");
  EXPECT_EQ(v, (std::vector<double>{1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(in.last_line(), 5);
  EXPECT_EQ(in.read_integers(1, "next"), std::vector<int>{9});
}

TEST(InpStreamArrays, MoreThanFiftyValuesOnALineAreAnError) {
  // CONTACT reads 50 words of an array line: values 51.. would be lost and the rest shifted.
  std::string line;
  for (int k = 1; k <= 60; ++k) line += std::to_string(k) + " ";
  InpStream in(line + "\n 100 101\n", "t.inp");
  try {
    (void)in.read_integers(52, "list");
    FAIL() << "60 values on one line were read";
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_EQ(e.offending(), "51");
    EXPECT_NE(e.message().find("more than 50 values on one line of list"), std::string::npos);
  }
  // An array that ends within the first 50 words ignores what follows (a label).
  InpStream short_line(line + "\n", "t.inp");
  const auto v = short_line.read_integers(50, "list");
  EXPECT_EQ(v[49], 50);
}

TEST(InpStreamArrays, AngleEntriesInMixedArrays) {
  InpStream in(" -1.0 10d  1.0 -10d\n", "t.inp");
  const auto v = in.read_reals(4, "table", [](std::size_t k) { return k % 2 == 1; });
  EXPECT_DOUBLE_EQ(v[1], 10.0 * kPi / 180.0);
  EXPECT_DOUBLE_EQ(v[3], -10.0 * kPi / 180.0);
}

TEST(InpStreamArrays, BadValueAndEndOfFile) {
  InpStream in(" 1 2\n x 4\n", "t.inp");
  try {
    in.read_reals(4, "B(1..4) of the IBASE=1 block");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.offending(), "x");
    EXPECT_NE(e.message().find("value 3 of B(1..4) of the IBASE=1 block"), std::string::npos);
  }
  InpStream eof(" 1 2\n", "t.inp");
  try {
    eof.read_reals(4, "B(1..4)");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(e.message().find("end of file while reading B(1..4) (2 of 4 values read)"),
              std::string::npos);
  }
}

TEST(InpStreamLines, WindowsLineEndingsAndMissingFinalNewline) {
  InpStream in(" 3 MODULE\r\n 1 2\r\n 7", "t.inp");
  EXPECT_EQ(in.read_group({{"M", kI}}, "m").integer(0), 3);
  const GroupValues g = in.read_group({{"A", kI}, {"B", kI}}, "ab");
  EXPECT_EQ(g.integer(1), 2);
  EXPECT_EQ(in.read_group({{"C", kI}}, "c").integer(0), 7);
  EXPECT_EQ(in.line_count(), 3);
}

// Fortran's READ gives an underflowing real as zero (or a subnormal); an overflowing one has no
// finite value. Neither inf nor nan is a Fortran number.
TEST(InpLexer, UnderflowReadsAsZeroOverflowAndNonNumbersAreRejected) {
  EXPECT_EQ(parse_fortran_real("1e-400"), 0.0);
  EXPECT_EQ(parse_fortran_real("-1.0d-999"), 0.0);
  EXPECT_TRUE(std::signbit(*parse_fortran_real("-1.0d-999")));
  EXPECT_GT(*parse_fortran_real("1e-310"), 0.0);  // subnormal, kept
  for (const char* bad : {"1e999", "-1.0D400", "inf", "nan", "Infinity", "0x1p3"})
    EXPECT_FALSE(parse_fortran_real(bad).has_value()) << bad;
}

}  // namespace
}  // namespace rollcontact::format
