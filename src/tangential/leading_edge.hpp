#pragma once
// Leading-edge correction of transient rolling with steps longer than an element (physics.md
// §9.4). A particle now within δq of the leading edge was outside the contact at the previous
// time: it has been in contact only since it crossed the edge, so only the part of the step
// after the edge counts as slip. Its rigid shift is scaled by f = (x_edge − x_I)/δq < 1 and its
// previous displacement is the one at the edge, where it entered, instead of the one at
// x_I + δq. The edge of a row is placed one element beyond its last contact element; with
// δq ≤ δx no contact element is affected.

#include <cstddef>
#include <vector>

#include "rollcontact/grid.hpp"

namespace rollcontact::tangential {

/// One contact element whose step began outside the contact.
struct LeadingEdgeEntry {
  std::size_t element = 0;  ///< the element I
  std::size_t edge = 0;     ///< the element at the row's leading edge (x_edge), outside contact
  double factor = 1.0;  ///< f = (x_edge − x_I)/δq ∈ (0, 1): the part of the step in contact
};

/// The entries of every row of `contact` for rolling direction `chi_rad` and step `dq_mm`.
/// Empty unless χ lies within 0.01 rad of 0 or π (rows are the rolling direction) and δq > δx.
/// Rows with fewer than two elements of the grid beyond their leading contact element are left
/// alone, as CONTACT does: there the edge is the end of the grid, not of the contact.
std::vector<LeadingEdgeEntry> leading_edge_entries(const Grid& grid,
                                                   const std::vector<char>& contact, double chi_rad,
                                                   double dq_mm);

}  // namespace rollcontact::tangential
