#include "fe_advice/value_checks.hpp"

#include <fmt/format.h>

#include <cmath>
#include <string>

#include "rollcontact/errors.hpp"

namespace rollcontact::fe_advice::detail {

namespace {

[[noreturn]] void reject(std::string_view field, double value, std::string_view why) {
  throw InvalidValueError(std::string(field), fmt::format(" = {}: {}", value, why));
}

}  // namespace

void require_positive(std::string_view field, double value) {
  if (!(std::isfinite(value) && value > 0.0))
    reject(field, value, "must be a finite number greater than 0");
}

void require_non_negative(std::string_view field, double value) {
  if (!(std::isfinite(value) && value >= 0.0))
    reject(field, value, "must be a finite number of at least 0");
}

void require_in_range(std::string_view field, double value, double lo, double hi) {
  if (!(std::isfinite(value) && value >= lo && value < hi))
    reject(field, value, fmt::format("must lie in [{}, {})", lo, hi));
}

}  // namespace rollcontact::fe_advice::detail
