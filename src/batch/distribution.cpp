#include "batch/distribution.hpp"

#include <algorithm>

namespace rollcontact::batch {

std::vector<std::string> SerialDistribution::map_gather(
    std::size_t n, std::size_t /*chunk*/, const std::function<std::string(std::size_t)>& body) {
  std::vector<std::string> out;
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(body(i));
  return out;
}

std::size_t default_chunk(std::size_t n, int processes) {
  const std::size_t p = static_cast<std::size_t>(std::max(1, processes));
  return std::max<std::size_t>(1, n / (16 * p));
}

}  // namespace rollcontact::batch
