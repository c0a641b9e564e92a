#pragma once
// The value checks of the FE advice: each throws InvalidValueError naming the field, in the
// words of model::validate ("field = value: must be ...").

#include <string_view>

namespace rollcontact::fe_advice::detail {

/// Finite and > 0.
void require_positive(std::string_view field, double value);
/// Finite and ≥ 0.
void require_non_negative(std::string_view field, double value);
/// Finite and in [lo, hi).
void require_in_range(std::string_view field, double value, double lo, double hi);

}  // namespace rollcontact::fe_advice::detail
