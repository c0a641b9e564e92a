// The whole-program rejection corpus tests/data/rejected/ (made by its generate.py, plus
// hand-written files): every file names on its first line the line and message fragment it must
// be rejected with. `rollcontact run` must exit with 2, name the file and line, and write
// nothing. Together with tests/data/malformed/ (reader level, also run through the CLI) this is
// the malformed-input corpus of issue 11.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "support/files.hpp"

namespace {

namespace fs = std::filesystem;

struct Expectation {
  int line = -1;
  std::string fragment;
};

/// `% expect: LINE: FRAGMENT` (or `#`), after an optional byte-order mark.
Expectation expectation_of(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string first;
  std::getline(in, first);
  if (first.rfind("\xEF\xBB\xBF", 0) == 0) first.erase(0, 3);
  const std::string key = " expect: ";
  const auto at = first.find(key);
  if (at != 1) return {};
  const std::string rest = first.substr(at + key.size());
  const auto colon = rest.find(": ");
  if (colon == std::string::npos) return {};
  return {std::stoi(rest.substr(0, colon)), rest.substr(colon + 2)};
}

using rollcontact::test_support::file_text;

TEST(CliRejectedInputs, EveryFileIsExitTwoAtItsLineAndNothingIsWritten) {
  const fs::path corpus = fs::path(ROLLCONTACT_TEST_DATA_DIR) / "rejected";
  const rollcontact::test_support::ScratchDir scratch("rc_cli_rejected");
  const fs::path& work = scratch.path();
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(corpus)) {
    const fs::path& source = entry.path();
    if (source.extension() == ".py") continue;
    const Expectation expect = expectation_of(source);
    ASSERT_GE(expect.line, 0) << source.filename() << ": no '% expect: LINE: FRAGMENT' header";
    const fs::path dir = work / source.filename();
    fs::create_directories(dir);
    const fs::path input = dir / source.filename();
    fs::copy_file(source, input);
    const fs::path stderr_file = work / (source.filename().string() + ".stderr");
    const std::string command = std::string(ROLLCONTACT_CLI) + " run " + input.string() +
                                " >/dev/null 2>" + stderr_file.string();
    const int status = std::system(command.c_str());
    const int code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    const std::string message = file_text(stderr_file);
    SCOPED_TRACE(source.filename().string() + ": " + message);
    EXPECT_EQ(code, 2);
    const std::string place =
        input.string() + (expect.line > 0 ? ":" + std::to_string(expect.line) + ":" : ":");
    EXPECT_NE(message.find(place), std::string::npos) << "expected " << place;
    EXPECT_NE(message.find(expect.fragment), std::string::npos);
    // Nothing written: the folder holds the input alone, unchanged.
    EXPECT_EQ(std::distance(fs::directory_iterator(dir), fs::directory_iterator()), 1);
    EXPECT_EQ(file_text(input), file_text(source));
    ++checked;
  }
  EXPECT_GE(checked, 100);
}

}  // namespace
