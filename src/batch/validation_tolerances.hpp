#pragma once
// Tolerances of `rollcontact validate`: which report quantities are compared with CONTACT's
// reference and how closely. default_tolerances() (validation_tolerances.cpp) is the one place
// where the numbers live; the reasons for each are written next to them there.

#include <map>
#include <string>
#include <string_view>

namespace rollcontact::batch {

/// Allowed |ours − reference| = max(minimum, relative·|reference| + absolute + per_fn·|FN|),
/// with FN the reference case's normal force (module 1: FZ(TR)); when the reference is printed
/// as exactly 0 (CONTACT filters noise-dominated values) at least zero_per_fn·|FN|.
struct Tolerance {
  double relative = 0;
  double absolute = 0;     ///< in the quantity's unit
  double per_fn = 0;       ///< times |FN|: the floor for a force component near zero
  double minimum = 0;      ///< floor of the allowed difference (element counts)
  double zero_per_fn = 0;  ///< times |FN|: the floor when the reference is a filtered 0
  bool count = false;      ///< an element count: excluded from the relative-difference statistics
};

/// Quantity name (report_parser.hpp key without `patch k/`) → tolerance. Quantities not in the
/// table are parsed but not compared.
struct ToleranceTable {
  std::map<std::string, Tolerance, std::less<>> by_quantity;

  /// The tolerance of a report key (`PMAX`, `patch 2/FN`), or nullptr if it is not compared.
  const Tolerance* find(std::string_view key) const;
};

/// The tolerances rollcontact is validated with.
ToleranceTable default_tolerances();

/// The tolerances for one example (the stem of its .inp): `base` with the example-specific
/// entries of spec/validation.md §3 (`wheelflat`: forces 1 %, PMAX 2 %).
ToleranceTable tolerances_for_example(ToleranceTable base, std::string_view example_stem);

/// The allowed difference for `reference` given the case's normal force `fn`.
double allowed_difference(const Tolerance& tolerance, double reference, double fn);

}  // namespace rollcontact::batch
