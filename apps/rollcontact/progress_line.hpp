#pragma once
// The progress line of long batch jobs (table, lookup): cases done, rate and time left, on a
// terminal only — quiet in pipes, in files and with -q, so that logs hold results, not
// carriage returns.

#include <chrono>
#include <cstddef>
#include <functional>
#include <string>

namespace rollcontact::cli {

/// A callback for batch progress (done cases), or an empty function when `quiet` or stderr is
/// not a terminal. `label` starts the line, `total` is the number of cases.
std::function<void(std::size_t)> make_progress_line(std::string label, std::size_t total,
                                                    bool quiet);

}  // namespace rollcontact::cli
