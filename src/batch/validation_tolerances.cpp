// THE tolerance table of `rollcontact validate` (issue "CONTACT-compatible reports … automatic
// validation suite", item 4; spec/validation.md §3).
//
// Both sides are printed numbers with 4 significant digits, so a rounding of up to one unit in
// the last digit (1e-3 relative for a mantissa near 1) is noise: 1e-3 relative is the floor.
//
// | Quantity                         | Allowed difference                 | Why |
// |----------------------------------|------------------------------------|----------------------------|
// | FN, FX, FY (module 1: FS,        | 1e-3·|ref| + 1e-6·FN               | contract of the issue;
// the | |   FX(TR), FY(TR), FZ(TR))        |                                    | FN term covers
// components  | |                                  |                                    | that are
// zero up to noise  | | MZ (module 1: MN)                | 5e-3·|ref| + 1e-6·FN               |
// validation.md §3: a moment | |                                  | | is a difference of large   |
// |                                  |                                    | contributions | | PMAX
// | 5e-3·|ref| + 1e-6·FN               | validation.md §3: maximum  | | | | of a single element |
// | APPROACH (PEN)                   | 1e-3·|ref|                         | contract / §3 | | CREEP
// X/Y, SHIFT X/Y (solved)    | 2e-3·|ref| + 1e-7                  | §3 (Newton iteration       | |
// |                                    | stops at its tolerance);   | | | | 1e-7 = noise of a zero
// | | NCON, NADH, NSLIP                | max(2, 1 % of ref) elements        | contract ±2; §3 adds
// 1 %   | |                                  |                                    | for large
// patches, where   | |                                  |                                    | more
// borderline elements   | |                                  |                                    |
// flip                       |
//
// Not compared: FN/G, FX/FSTAT/FN, FY/FSTAT/FN (derived from the forces above), ELEN, FRIC,
// MAX(T1,T2), NPOT (input), NPLAST, INORM, ITANG (iteration counts differ by design).

#include "batch/validation_tolerances.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::batch {

const Tolerance* ToleranceTable::find(std::string_view key) const {
  // `patch k/NAME`: module-1 patches use the same tolerances as module 3.
  if (const auto slash = key.rfind('/');
      slash != std::string_view::npos && key.substr(0, 6) == "patch ")
    key.remove_prefix(slash + 1);
  const auto it = by_quantity.find(key);
  return it == by_quantity.end() ? nullptr : &it->second;
}

ToleranceTable default_tolerances() {
  const Tolerance normal_force{.relative = 1e-3, .per_fn = 1e-6};
  const Tolerance force{.relative = 1e-3, .per_fn = 1e-6, .zero_per_fn = 1e-4};
  const Tolerance moment{.relative = 5e-3, .per_fn = 1e-6, .zero_per_fn = 1e-4};
  const Tolerance max_pressure{.relative = 5e-3, .per_fn = 1e-6};
  const Tolerance approach{.relative = 1e-3};
  const Tolerance solved_creepage{.relative = 2e-3, .absolute = 1e-7};
  const Tolerance element_count{.relative = 1e-2, .minimum = 2, .count = true};

  ToleranceTable t;
  for (const char* name : {"FN", "FZ(TR)"}) t.by_quantity.emplace(name, normal_force);
  for (const char* name : {"FX", "FY", "FS", "FX(TR)", "FY(TR)"})
    t.by_quantity.emplace(name, force);
  for (const char* name : {"MZ", "MN"}) t.by_quantity.emplace(name, moment);
  t.by_quantity.emplace("PMAX", max_pressure);
  t.by_quantity.emplace("APPROACH", approach);
  for (const char* name : {"CREEP X", "CREEP Y", "SHIFT X", "SHIFT Y"})
    t.by_quantity.emplace(name, solved_creepage);
  for (const char* name : {"NCON", "NADH", "NSLIP"}) t.by_quantity.emplace(name, element_count);
  return t;
}

double allowed_difference(const Tolerance& tolerance, double reference, double fn) {
  const double allowed = tolerance.relative * std::abs(reference) + tolerance.absolute +
                         tolerance.per_fn * std::abs(fn);
  // A hair of slack so that a difference of exactly the tolerance (1.000E+04 vs 1.001E+04) is
  // not decided by the binary representation of the printed decimals.
  const double floor = reference == 0
                           ? std::max(tolerance.minimum, tolerance.zero_per_fn * std::abs(fn))
                           : tolerance.minimum;
  return std::max(floor, allowed * (1 + 1e-9));
}

}  // namespace rollcontact::batch
