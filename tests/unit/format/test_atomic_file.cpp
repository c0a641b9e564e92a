#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "format/text/atomic_file.hpp"
#include "rollcontact/errors.hpp"

namespace rollcontact::format {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const char* name) {
  const fs::path d =
      fs::temp_directory_path() / fs::path(std::string("rollcontact_atomic_") + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

TEST(AtomicFile, WritesAndReplacesWithoutLeftovers) {
  const fs::path d = fresh_dir("replace");
  const fs::path f = d / "case.out";
  write_file_atomically(f, "first\n");
  EXPECT_EQ(slurp(f), "first\n");
  write_file_atomically(f, std::string("second\0line", 11));
  EXPECT_EQ(slurp(f), std::string("second\0line", 11));
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);
  fs::remove_all(d);
}

TEST(AtomicFile, MissingFolderThrowsWithPath) {
  const fs::path d = fresh_dir("missing");
  const fs::path f = d / "no_such_folder" / "x.out";
  try {
    write_file_atomically(f, "x");
    FAIL() << "expected rollcontact::Error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(f.string()), std::string::npos) << e.what();
  }
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 0);
  fs::remove_all(d);
}

TEST(AtomicFile, TargetIsAFolderThrowsAndCleansUp) {
  const fs::path d = fresh_dir("isdir");
  fs::create_directories(d / "taken");
  EXPECT_THROW(write_file_atomically(d / "taken", "x"), Error);
  EXPECT_EQ(std::distance(fs::directory_iterator(d), fs::directory_iterator()), 1);
  fs::remove_all(d);
}

}  // namespace
}  // namespace rollcontact::format

TEST(AtomicFile, WritesThroughDevicesInsteadOfReplacingThem) {
  // Renaming a temporary over /dev/null would replace the device with a regular file.
  rollcontact::format::write_file_atomically("/dev/null", "nothing\n");
  EXPECT_FALSE(std::filesystem::is_regular_file("/dev/null"));
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
}
