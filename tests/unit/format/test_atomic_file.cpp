#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "format/text/atomic_file.hpp"
#include "rollcontact/errors.hpp"
#include "support/files.hpp"

namespace rollcontact::format {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(AtomicFile, WritesAndReplacesWithoutLeftovers) {
  const test_support::ScratchDir scratch("rollcontact_atomic_replace");
  const fs::path& d = scratch.path();
  const fs::path f = d / "case.out";
  write_file_atomically(f, "first\n");
  EXPECT_EQ(slurp(f), "first\n");
  write_file_atomically(f, std::string("second\0line", 11));
  EXPECT_EQ(slurp(f), std::string("second\0line", 11));
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);
}

TEST(AtomicFile, MissingFolderThrowsWithPath) {
  const test_support::ScratchDir scratch("rollcontact_atomic_missing");
  const fs::path& d = scratch.path();
  const fs::path f = d / "no_such_folder" / "x.out";
  try {
    write_file_atomically(f, "x");
    FAIL() << "expected rollcontact::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(f.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 0);
}

TEST(AtomicFile, TargetIsAFolderThrowsAndCleansUp) {
  const test_support::ScratchDir scratch("rollcontact_atomic_isdir");
  const fs::path& d = scratch.path();
  fs::create_directories(d / "taken");
  EXPECT_THROW(write_file_atomically(d / "taken", "x"), Error);
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);
}

TEST(AtomicFile, PiecesAppearOnlyAtCommit) {
  const test_support::ScratchDir scratch("rollcontact_atomic_pieces");
  const fs::path& d = scratch.path();
  const fs::path f = d / "run.out";
  write_file_atomically(f, "previous run\n");
  {
    AtomicFileWriter w(f);
    w.append("case 1\n");
    w.append("case 2\n");
    EXPECT_EQ(slurp(f), "previous run\n");  // the old file stays until the new one is whole
    w.commit();
  }
  EXPECT_EQ(slurp(f), "case 1\ncase 2\n");
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);
}

TEST(AtomicFile, AnUncommittedWriterLeavesNothing) {
  // A run that fails half-way: neither half a file nor its temporary remains.
  const test_support::ScratchDir scratch("rollcontact_atomic_uncommitted");
  const fs::path& d = scratch.path();
  {
    AtomicFileWriter w(d / "run.out");
    w.append("case 1\n");
    EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 0);
}

}  // namespace
}  // namespace rollcontact::format

TEST(AtomicFile, WritesThroughDevicesInsteadOfReplacingThem) {
  // Renaming a temporary over /dev/null would replace the device with a regular file.
  rollcontact::format::write_file_atomically("/dev/null", "nothing\n");
  EXPECT_FALSE(std::filesystem::is_regular_file("/dev/null"));
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}
