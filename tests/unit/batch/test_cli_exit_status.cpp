// The CLI's documented exit statuses, checked on the real program: 0 success, 1 a case failed,
// 2 unreadable input or bad command line with nothing written.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <set>
#include <string>

#include "support/files.hpp"

namespace {

namespace fs = std::filesystem;

int exit_status(const std::string& arguments) {
  const std::string command = std::string(ROLLCONTACT_CLI) + " " + arguments + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

class CliExitStatus : public ::testing::Test {
 protected:
  void SetUp() override {
    scratch_.emplace("rc_cli_exit_" +
                     std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    dir_ = scratch_->path();
  }
  std::optional<rollcontact::test_support::ScratchDir> scratch_;
  fs::path dir_;
};

TEST_F(CliExitStatus, HelpAndVersionSucceed) {
  EXPECT_EQ(exit_status("--help"), 0);
  EXPECT_EQ(exit_status("--version"), 0);
}

TEST_F(CliExitStatus, BadCommandLineIsTwo) {
  EXPECT_EQ(exit_status(""), 2);  // a subcommand is required
  EXPECT_EQ(exit_status("frobnicate"), 2);
  EXPECT_EQ(exit_status("run --no-such-option x.inp"), 2);
  EXPECT_EQ(exit_status("run " + (dir_ / "missing.inp").string()), 2);
}

TEST_F(CliExitStatus, MalformedInputIsTwoAndWritesNothing) {
  const fs::path malformed = fs::path(ROLLCONTACT_TEST_DATA_DIR) / "malformed";
  int checked = 0;
  for (const auto& entry : fs::directory_iterator(malformed)) {
    if (entry.path().extension() != ".inp") continue;
    // A missing influence-coefficient file (C=9) is an error only for strict reading; the CLI
    // reports it as a failed case (status 1), like CONTACT. Covered below.
    if (entry.path().filename() == "missing_c9_file.inp") continue;
    const fs::path copy = dir_ / entry.path().filename();
    fs::copy_file(entry.path(), copy);
    EXPECT_EQ(exit_status("run " + copy.string()), 2) << entry.path().filename();
    fs::path out = copy, json = copy;
    EXPECT_FALSE(fs::exists(out.replace_extension(".out"))) << entry.path().filename();
    EXPECT_FALSE(fs::exists(json.replace_extension(".json"))) << entry.path().filename();
    ++checked;
  }
  EXPECT_GT(checked, 50);
}

TEST_F(CliExitStatus, MissingInfluenceFileFailsTheCaseWithStatusOne) {
  const fs::path copy = dir_ / "missing_c9_file.inp";
  fs::copy_file(fs::path(ROLLCONTACT_TEST_DATA_DIR) / "malformed" / "missing_c9_file.inp", copy);
  EXPECT_EQ(exit_status("run " + copy.string()), 1);
  EXPECT_TRUE(fs::exists(dir_ / "missing_c9_file.out"));  // with the case's ERROR line
}

TEST_F(CliExitStatus, ValidInputSucceedsAndWritesReport) {
  const fs::path source = fs::path(ROLLCONTACT_EXAMPLES_DIR) / "cattaneo.inp";
  if (!fs::exists(source)) GTEST_SKIP() << "CONTACT examples not present";
  const fs::path copy = dir_ / "cattaneo.inp";
  fs::copy_file(source, copy);
  EXPECT_EQ(exit_status("run " + copy.string()), 0);
  EXPECT_TRUE(fs::exists(dir_ / "cattaneo.out"));
  EXPECT_TRUE(fs::exists(dir_ / "cattaneo.json"));
}

// Nothing of the user's is lost (issue 11): an input named like an output is refused before it is
// read twice, and a wrong output folder is found before anything is solved.
TEST_F(CliExitStatus, AnInputNamedLikeItsOutputIsRefusedAndKept) {
  const fs::path source =
      fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples" / "hertz_normal.inp";
  for (const char* name : {"case.out", "case.json"}) {
    const fs::path input = dir_ / name;
    fs::copy_file(source, input, fs::copy_options::overwrite_existing);
    EXPECT_EQ(exit_status("run " + input.string()), 2) << name;
    EXPECT_EQ(fs::file_size(input), fs::file_size(source)) << name << " was overwritten";
  }
}

TEST_F(CliExitStatus, AnUnusableOutputFolderIsTwoBeforeSolving) {
  const fs::path source =
      fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples" / "hertz_normal.inp";
  const fs::path file = dir_ / "a_file";
  std::ofstream(file) << "x";
  EXPECT_EQ(exit_status("run -o " + file.string() + " " + source.string()), 2);
  EXPECT_EQ(exit_status("run -o " + (file / "below").string() + " " + source.string()), 2);
  EXPECT_EQ(exit_status("run -o /proc/rollcontact-out " + source.string()), 2);  // read-only
  EXPECT_EQ(fs::file_size(file), 1u);
}

TEST_F(CliExitStatus, EveryRepositoryExampleWritesItsOwnOutputs) {
  const fs::path examples = fs::path(ROLLCONTACT_TEST_DATA_DIR) / ".." / ".." / "examples";
  std::set<fs::path> stems;
  int inputs = 0;
  for (const auto& entry : fs::recursive_directory_iterator(examples)) {
    const fs::path& p = entry.path();
    if (p.extension() != ".inp" && p.extension() != ".toml") continue;
    ++inputs;
    EXPECT_TRUE(stems.insert(p.parent_path() / p.stem()).second)
        << p << " writes the same .out/.json as another example";
  }
  EXPECT_GE(inputs, 14);
}

TEST_F(CliExitStatus, DevicesAreRefusedAtOnce) {
  // Used to grow to 1.9 GB in 4 s and never end.
  EXPECT_EQ(exit_status("run /dev/zero"), 2);
  EXPECT_EQ(exit_status("run /dev/urandom"), 2);
}

TEST_F(CliExitStatus, ExampleLeavesNothingInTheWorkingDirectory) {
  EXPECT_EQ(exit_status("example -q --output-dir " + (dir_ / "named").string()), 0);
  EXPECT_TRUE(fs::exists(dir_ / "named" / "example.inp"));
  EXPECT_TRUE(fs::exists(dir_ / "named" / "example.out"));
  const fs::path cwd = dir_ / "cwd", tmp = dir_ / "tmp";
  fs::create_directories(cwd);
  fs::create_directories(tmp);
  // The example's own folder goes to the temporary folder (TMPDIR: here, so that it is removed).
  const std::string command = "cd " + cwd.string() + " && TMPDIR=" + tmp.string() + " " +
                              std::string(ROLLCONTACT_CLI) + " example -q >/dev/null 2>&1";
  EXPECT_EQ(std::system(command.c_str()), 0);
  EXPECT_TRUE(fs::is_empty(cwd)) << "example wrote into the working directory";
  int folders = 0;
  for (const auto& entry : fs::directory_iterator(tmp))
    folders += fs::exists(entry.path() / "example.out");
  EXPECT_EQ(folders, 1) << "the example's outputs belong in a new temporary folder";
}

}  // namespace
