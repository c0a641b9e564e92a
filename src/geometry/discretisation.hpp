#pragma once
// From a patch problem's potential-contact and geometry description to the element grid and the
// undeformed distance h per element (spec/physics.md §2, §4, §8).

#include <cstdint>
#include <vector>

#include "geometry/hertz.hpp"
#include "rollcontact/model/patch_problem.hpp"
#include "rollcontact/model/validation.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::geometry {

/// Value of h for elements excluded by the planform (never in contact).
inline constexpr double excluded_distance = 1e30;

using model::PotentialContact;
using model::UndeformedDistance;

/// IPLAN=4 rectangles that feel each other only in part (physics.md §4): the rectangle of each
/// element (the first containing it; 0 for excluded elements) and the symmetric factors
/// f(a, b) with f(a, a) = 1, row-major. n_parts = 1 and empty vectors: full interaction.
struct PlanformParts {
  int n_parts = 1;
  std::vector<std::uint8_t> part;
  std::vector<double> factor;
};
/// Upper bound on NPATCH: each part costs one influence product per application.
inline constexpr int kMaxPlanformPatches = 64;

struct Discretisation {
  Grid grid;
  std::vector<double> h;  ///< undeformed distance without approach [mm], excluded = 1e30
  HertzReport hertz;      ///< present for Hertzian IPOTCN < 0
  PlanformParts parts;    ///< IPLAN=4 attenuation between rectangles
};

/// Builds grid and undeformed distance. For Hertzian options the Hertz solution uses the normal
/// force or the approach of problem.normal and E* of `material`. Throws GeometryError when the
/// data are inadmissible (e.g. every element excluded, MX·MY too large).
Discretisation build_discretisation(const model::PatchProblem& problem,
                                    const CombinedMaterial& material);

/// Largest admissible number of elements MX·MY, and the range of element sizes DX, DY [mm] the
/// influence coefficients represent (the model's, shared with every front end).
inline constexpr long long max_grid_elements = 2'000'000;
inline constexpr double min_element_size = model::kMinElementSize_mm;
inline constexpr double max_element_size = model::kMaxElementSize_mm;

/// Grid of the potential contact for IPOTCN 1..4 (no Hertz needed). Throws ProblemError for
/// Hertzian or unknown IPOTCN and for grids failing validate_grid (IPOTCN 4 needs MX, MY ≥ 2).
Grid rectangular_grid(const model::PotentialContact& pot);

/// Hertz solution of a Hertzian option IPOTCN −1…−6 (−6: semi-axes a and b = (BNEG+BPOS)/2)
/// for a prescribed FN [N] or PEN [mm]; `estar` = E* [N/mm²]. The report's scale is SCALE.
/// 2-D options (−4, −5) need HertzLoad::Force. Throws ProblemError for inadmissible data.
HertzReport hertz_for_potential(const model::PotentialContact& pot, HertzLoad load, double value,
                                double estar);

/// Grid of a Hertzian option from its Hertz solution (spec/physics.md §2): [−s·a, s·a] in x;
/// in y [−s·b, s·b] (3-D, SDEC) or, for 2-D, MY rows of which n_int cover the strip [−b, b].
Grid hertzian_grid(const model::PotentialContact& pot, const HertzReport& hertz);

/// Throws ProblemError unless 1 ≤ MX, MY, MX·MY ≤ max_grid_elements, min_element_size ≤ DX, DY ≤
/// max_element_size and the corner is finite.
void validate_grid(const Grid& grid);

/// Undeformed distance of IBASE 1/2/3/9 with IPLAN 1/2/3/4 on `grid`, evaluated at element
/// centres [mm]; excluded elements get excluded_distance. Throws ProblemError for missing or
/// inconsistent data (coefficient counts, NN < 2, DY1 ≤ 0, RM = 0, B7/B8 = 0, IBASE 9 count
/// ≠ MX·MY, all elements excluded, IPLAN 4 limits or factors outside [0, 1]).
std::vector<double> undeformed_distance(const Grid& grid,
                                        const model::UndeformedDistance& geometry);

/// The IPLAN=4 parts of `grid` (n_parts = 1 for other planforms or when every factor is 1).
PlanformParts planform_parts(const Grid& grid, const model::UndeformedDistance& geometry);

}  // namespace rollcontact::geometry
