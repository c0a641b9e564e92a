#pragma once
// Kernels from a table of influence coefficients (CONTACT C=9, spec/inp-format.md §8.5) instead
// of the closed forms.

#include "elastic/influence.hpp"

namespace rollcontact::elastic {

/// Largest difference between the table's element size and the grid's [mm] (inp-format.md §8.5).
inline constexpr double kTableElementTolerance_mm = 1e-5;

/// Component c of material.table on the grid, divided by material.g: offsets beyond the table
/// are 0 (a smaller file grid zero-padded), offsets beyond the grid are not used (a larger one
/// truncated). A shift (rolling: the observation point one step downstream, physics.md §3.2)
/// must be a whole number of elements in x and y: C′ is then C read that many offsets further,
/// exactly; other shifts would need the coefficients between the table's points and are
/// refused (NotSupportedError). Throws ProblemError when the element sizes differ.
Kernel table_kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                    double shift_x_mm, double shift_y_mm);

}  // namespace rollcontact::elastic
