// Bounded reading (issue 11): devices, folders and oversized files are refused before a byte is
// read; a byte-order mark is skipped; text past CONTACT's 256 columns is an error at its line and
// column; a value missing on a line is pointed at although the error surfaces lines later.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "format/inp/inp_reader.hpp"
#include "format/text/input_file.hpp"
#include "format/toml/toml_case_reader.hpp"
#include "rollcontact/errors.hpp"
#include "support/files.hpp"

namespace rollcontact::format {
namespace {

namespace fs = std::filesystem;

const fs::path kRepoExamples = fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";

using rollcontact::test_support::file_text;

/// The message of the InputError that `f` throws ("" if none).
template <typename F>
std::string error_of(F f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BoundedReading, DevicesAndFoldersAreRefusedAtOnce) {
  for (const char* path : {"/dev/zero", "/dev/urandom", "/tmp"}) {
    const std::string m = error_of([&] { (void)read_input_file(path, "input file"); });
    EXPECT_NE(m.find("is not a regular file"), std::string::npos) << path << ": " << m;
  }
  EXPECT_NE(error_of([] { (void)read_inp_file("/dev/zero"); }).find("not a regular file"),
            std::string::npos);
}

TEST(BoundedReading, FilesOverTheLimitAreRefusedBeforeReading) {
  const rollcontact::test_support::ScratchDir scratch("rc_bounded");
  const fs::path big = scratch / "rc_bounded_big.inp";
  { std::ofstream(big) << "x"; }
  fs::resize_file(big, kMaxInputBytes + 1);  // sparse: costs no disk and no time
  const std::string m = error_of([&] { (void)read_input_file(big, "input file"); });
  EXPECT_NE(m.find("more than the limit"), std::string::npos) << m;
}

TEST(BoundedReading, AByteOrderMarkIsSkipped) {
  const std::string bom = "\xEF\xBB\xBF";
  const auto plain = read_inp_string(file_text(kRepoExamples / "hertz_normal.inp"), "a.inp");
  const auto marked = read_inp_string(bom + file_text(kRepoExamples / "hertz_normal.inp"), "b.inp");
  ASSERT_EQ(plain.size(), marked.size());
  EXPECT_EQ(marked[0].kinematics.fn, plain[0].kinematics.fn);
  EXPECT_NO_THROW((void)read_toml_string(
      bom + file_text(kRepoExamples / "toml" / "hertz_normal.toml"), "c.toml"));
}

TEST(BoundedReading, TextPastColumn256IsAnErrorAtItsLineAndColumn) {
  std::string text = file_text(kRepoExamples / "hertz_normal.inp");
  // Line 7 (FN CKSI CETA CPHI) padded so that its last value starts at column 261.
  const std::size_t start = text.find("1000.0");
  ASSERT_NE(start, std::string::npos);
  const std::size_t line_start = text.rfind('\n', start) + 1;
  text.insert(line_start, std::string(260, ' '));
  const std::string m = error_of([&] { (void)read_inp_string(text, "long.inp"); });
  EXPECT_NE(m.find("long.inp:7:"), std::string::npos) << m;
  EXPECT_NE(m.find("text from column 263"), std::string::npos) << m;
  // A comment that runs past column 256 loses nothing: accepted as CONTACT accepts it.
  std::string commented = file_text(kRepoExamples / "hertz_normal.inp");
  commented.insert(commented.find('\n', commented.find("1000.0")), "  %" + std::string(300, '-'));
  EXPECT_NO_THROW((void)read_inp_string(commented, "comment.inp"));
  // A comment that starts past column 256 loses nothing either (CONTACT cuts the line there).
  std::string late = file_text(kRepoExamples / "hertz_normal.inp");
  late.insert(late.find('\n', late.find("1000.0")), std::string(280, ' ') + "% a late comment");
  EXPECT_NO_THROW((void)read_inp_string(late, "late.inp"));
}

TEST(BoundedReading, AMissingValueIsPointedAtItsLine) {
  std::string text = file_text(kRepoExamples / "rectangle_quadratic.inp");
  const std::string full = "  500.0  0.0  0.0  0.0 ";
  const std::size_t at = text.find(full);
  ASSERT_NE(at, std::string::npos);
  text.replace(at, full.size(), "  500.0  0.0  0.0 ");  // CPHI missing on line 7
  const std::string m = error_of([&] { (void)read_inp_string(text, "miss.inp"); });
  EXPECT_NE(m.find("is a value missing on line 7?"), std::string::npos) << m;
}

}  // namespace
}  // namespace rollcontact::format
