#pragma once
// Files for tests: whole-file reading for byte-for-byte comparisons, and scratch directories.

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <string_view>
#include <system_error>

namespace rollcontact::test_support {

/// The bytes of `path` ("" when it cannot be opened).
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// A fresh, empty directory under the system's temporary folder for one test's files, removed
/// with its contents when the object goes out of scope (also when an assertion ends the test).
/// Its name carries `name`, the process id and a per-process count, so that test programs run
/// concurrently (ctest -j, a release and a sanitizer build side by side) never share one.
class ScratchDir {
 public:
  explicit ScratchDir(std::string_view name) : path_(unique_path(name)) {
    std::filesystem::remove_all(path_);
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;  // a destructor must not throw; a leftover folder is harmless
    std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;

  const std::filesystem::path& path() const noexcept { return path_; }
  std::filesystem::path operator/(const std::filesystem::path& child) const {
    return path_ / child;
  }

 private:
  static std::filesystem::path unique_path(std::string_view name) {
    static std::atomic<int> count{0};
    return std::filesystem::temp_directory_path() /
           (std::string("rollcontact-") + std::string(name) + "-" + std::to_string(::getpid()) +
            "-" + std::to_string(count++));
  }

  std::filesystem::path path_;
};

}  // namespace rollcontact::test_support
