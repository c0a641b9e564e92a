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
// Module 1 (wheel/rail, validation.md §3): the patch quantities come out of a contact search, a
// grid placed on its reference point and a vertical-force iteration, each with its own rounding,
// so forces get 0.5 % + 2e-4·FZ (FX(TR), FY(TR), FX/FY/FZ(WS), patch FN, FX, FS), PMAX 1 %,
// the spin moment MN 0.5 % + 1e-3 mm·FZ (FZ on a lever arm of 1 µm, 1/200 of the benchmark's
// element: the undeformed distance of CONTACT's D=2 comes from interpolated surface meshes, ours
// is exact, which moves MN of flange contacts by 7–11 N·mm, docs/decisions.md), the reference
// location 5e-3 mm (a patch combined from two regions is their weighted centre and moves with
// z_ws by up to 150 mm/mm, while the reference prints z_ws to 1e-4 mm; single-region patches
// agree to 3e-4 mm), the contact angle 1e-4 rad,
// Z_WS 2e-3 mm, the creepages 0.5 % + 2e-6 (a location error of 1e-3 mm on a 460 mm wheel),
// CHI/DQ/VELOC 1e-3 relative; FZ(TR) keeps the 1e-3 of a prescribed force. Patch keys
// (`patch k/NAME`) look for `patch/NAME` first.
//
// MAX(T1,T2) (H >= 1): 1 % relative (validation.md §3); a maximum of single elements like PMAX.
// Subsurface extremes (`SUBS b/SIGVM` …, S >= 1): 5e-3 relative + 0.001 N/mm², like PMAX; their
// locations are not compared (near-equal maxima in neighbouring points).
//
// Not compared: FN/G, FX/FSTAT/FN, FY/FSTAT/FN, FX/FN, FS/FN (derived from the forces above),
// ELEN, FRIC,
// NPOT (input), NPLAST, INORM, ITANG (iteration counts differ by design).

#include "batch/validation_tolerances.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::batch {

const Tolerance* ToleranceTable::find(std::string_view key) const {
  // `[patch k/]SUBS b/NAME`: a subsurface extreme of block b, `SUBS/NAME`.
  if (const auto subs = key.find("SUBS "); subs != std::string_view::npos) {
    const auto it = by_quantity.find("SUBS/" + std::string(key.substr(key.rfind('/') + 1)));
    return it == by_quantity.end() ? nullptr : &it->second;
  }
  // `patch k/NAME`: module-1 patch quantities, `patch/NAME` where module 1 differs from module 3.
  // NAME may hold slashes itself (FX/FSTAT/FN, not compared): only the prefix is cut.
  if (const auto slash = key.find('/');
      slash != std::string_view::npos && key.substr(0, 6) == "patch ") {
    key.remove_prefix(slash + 1);
    const auto m1 = by_quantity.find("patch/" + std::string(key));
    if (m1 != by_quantity.end()) return &m1->second;
  }
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
  t.by_quantity.emplace("MAX(T1,T2)", Tolerance{.relative = 1e-2});
  // Subsurface extremes: maxima over points like PMAX, of sums over every loaded element, so
  // 5e-3 relative; 0.001 N/mm² for an extreme near zero (the printed resolution).
  for (const char* name :
       {"SIGHYD", "SIGVM", "SIGTR", "SIGMA1", "SIGMA3", "SIGXX", "SIGYY", "SIGZZ"})
    t.by_quantity.emplace(std::string("SUBS/") + name,
                          Tolerance{.relative = 5e-3, .absolute = 1e-3});

  // Module 1.
  const Tolerance wheelrail_force{.relative = 5e-3, .per_fn = 2e-4};
  const Tolerance location{.absolute = 5e-3};
  for (const char* name : {"FX(TR)", "FY(TR)", "FX(WS)", "FY(WS)", "FZ(WS)"})
    t.by_quantity.insert_or_assign(name, wheelrail_force);
  // Conformal patches (D=4) print the forces turned into the planar frame (BAR_) and the
  // normal force integrated in the curvilinear one (TILDE_FN) instead of FN, FX, FS.
  for (const char* name : {"patch/FN", "patch/FX", "patch/FS", "patch/BAR_FN", "patch/BAR_FX",
                           "patch/BAR_FS", "patch/TILDE_FN"})
    t.by_quantity.emplace(name, wheelrail_force);
  t.by_quantity.emplace("patch/MN", Tolerance{.relative = 5e-3, .per_fn = 1e-3});
  t.by_quantity.emplace("patch/PMAX", Tolerance{.relative = 1e-2});
  t.by_quantity.emplace("patch/APPROACH", Tolerance{.relative = 5e-3, .absolute = 2e-4});
  for (const char* name :
       {"XCP(TR)", "YCP(TR)", "ZCP(TR)", "YCP(R)", "ZCP(R)", "XCP(W)", "YCP(W)", "ZCP(W)"})
    t.by_quantity.emplace(std::string("patch/") + name, location);
  t.by_quantity.emplace("patch/DELTCP(TR)", Tolerance{.absolute = 1.05e-4});
  for (const char* name : {"CKSI", "CETA", "CPHI"})
    t.by_quantity.emplace(std::string("patch/") + name,
                          Tolerance{.relative = 5e-3, .absolute = 2e-6});
  for (const char* name : {"CHI", "DQ", "VELOC"})
    t.by_quantity.emplace(std::string("patch/") + name,
                          Tolerance{.relative = 1e-3, .absolute = 1e-6});
  t.by_quantity.emplace("Z_WS", Tolerance{.absolute = 2e-3});
  return t;
}

ToleranceTable tolerances_for_example(ToleranceTable t, std::string_view example_stem) {
  if (example_stem == "wheelflat") {
    // Out-of-round wheel (validation.md §3): the forces 1 % (+ the module's 2e-4·FZ floor for
    // components near zero), PMAX 2 %: the measured slices are spline surfaces whose
    // micrometre-level differences move the patch over the flat.
    const Tolerance force{.relative = 1e-2, .per_fn = 2e-4};
    for (const char* name :
         {"FX(TR)", "FY(TR)", "FX(WS)", "FY(WS)", "FZ(WS)", "patch/FN", "patch/FX", "patch/FS"})
      t.by_quantity.insert_or_assign(name, force);
    t.by_quantity.insert_or_assign("patch/PMAX", Tolerance{.relative = 2e-2});
  }
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
