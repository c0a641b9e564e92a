#include "progress_line.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>

namespace rollcontact::cli {

std::function<void(std::size_t)> make_progress_line(std::string label, std::size_t total,
                                                    bool quiet) {
  if (quiet || isatty(fileno(stderr)) == 0) return {};
  const auto start = std::chrono::steady_clock::now();
  return [label = std::move(label), total, start](std::size_t done) {
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const double rate = s > 0.0 ? static_cast<double>(done) / s : 0.0;
    const double left = rate > 0.0 ? static_cast<double>(total - done) / rate : 0.0;
    fmt::print(stderr, "\r{}: {}/{} cases, {:.0f} cases/s, {:.0f} s left   ", label, done, total,
               rate, left);
    if (done == total) fmt::print(stderr, "\n");
    std::fflush(stderr);
  };
}

}  // namespace rollcontact::cli
