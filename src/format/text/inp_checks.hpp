#pragma once
// Range checks used while reading .inp groups; each failure names the quantity, its value and
// the admissible range, at the line the value came from.

#include <fmt/format.h>

#include <string_view>

#include "format/text/inp_stream.hpp"

namespace rollcontact::format {

/// Integer in [lo, hi]; message "NAME = v outside lo..hi".
inline void require_int_range(const InpStream& in, int line, std::string_view name, int value,
                              int lo, int hi) {
  if (value < lo || value > hi) {
    in.fail(line, fmt::format("{} = {} outside {}..{}", name, value, lo, hi));
  }
}

/// Real in [lo, hi]; message "NAME = v outside [lo, hi]".
inline void require_real_range(const InpStream& in, int line, std::string_view name, double value,
                               double lo, double hi) {
  if (!(value >= lo && value <= hi)) {
    in.fail(line, fmt::format("{} = {} outside [{}, {}]", name, value, lo, hi));
  }
}

/// Real >= lo; message "NAME = v must be at least lo".
inline void require_at_least(const InpStream& in, int line, std::string_view name, double value,
                             double lo) {
  if (!(value >= lo)) in.fail(line, fmt::format("{} = {} must be at least {}", name, value, lo));
}

/// Real > 0; message "NAME = v must be positive".
inline void require_positive(const InpStream& in, int line, std::string_view name, double value) {
  if (!(value > 0.0)) in.fail(line, fmt::format("{} = {} must be positive", name, value));
}

}  // namespace rollcontact::format
