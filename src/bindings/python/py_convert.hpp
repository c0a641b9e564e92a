#pragma once
// Solutions as Python objects: dicts of scalars with the fields as NumPy arrays of shape
// (my, mx) — row iy, column ix, the grid's own order (x fastest) — that view the solution's
// memory without copying; the arrays keep the solution alive. Units: mm, N, N/mm², rad.

#include <pybind11/pybind11.h>

#include "rollcontact/solution.hpp"
#include "rollcontact/wheelrail.hpp"

namespace rollcontact::python {

/// A module-3 solution (or one wheel/rail patch's): totals, statistics, grid and fields.
pybind11::dict solution_to_dict(Solution solution);

/// A wheel/rail solution: totals on the rail, wheelset height and one dict per patch.
pybind11::dict wheelrail_to_dict(WheelRailSolution solution);

}  // namespace rollcontact::python
