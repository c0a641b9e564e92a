#include "batch/temporary_folder.hpp"

#include <random>

#include "rollcontact/errors.hpp"

namespace rollcontact::batch {

std::filesystem::path new_temporary_folder(const std::string& prefix) {
  std::random_device seed;
  std::mt19937_64 random(seed());
  const auto base = std::filesystem::temp_directory_path();
  for (int attempt = 0; attempt < 100; ++attempt) {
    auto dir = base / (prefix + "-" + std::to_string(random() % 1000000000ULL));
    if (std::filesystem::create_directory(dir)) return dir;
  }
  throw Error("cannot create a temporary folder in " + base.string());
}

}  // namespace rollcontact::batch
