#pragma once
// Whole-file reading for tests that compare inputs and outputs byte for byte.

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace rollcontact::test_support {

/// The bytes of `path` ("" when it cannot be opened).
inline std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace rollcontact::test_support
