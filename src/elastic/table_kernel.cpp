#include "elastic/table_kernel.hpp"

#include <fmt/format.h>

#include <cmath>

#include "rollcontact/errors.hpp"

namespace rollcontact::elastic {

namespace {

using Table = model::InfluenceTable;

Table::Component table_component(Component c) {
  switch (c) {
    case Component::nn:
      return Table::zz;
    case Component::xx:
      return Table::xx;
    case Component::yy:
      return Table::yy;
    case Component::xy:
      return Table::xy;
    case Component::yx:
      return Table::yx;
    case Component::xn:
      return Table::xz;
    case Component::yn:
      return Table::yz;
    case Component::nx:
      return Table::zx;
    case Component::ny:
      return Table::zy;
  }
  return Table::zz;
}

/// The shift [mm] as a whole number of elements of size h [mm].
int whole_steps(double shift_mm, double h_mm, char axis, const Table& t) {
  const double steps = std::round(shift_mm / h_mm);
  // Relative to the element: a rolling step DQ = DX typed with a few digits still counts.
  if (std::abs(shift_mm - steps * h_mm) > 1e-6 * h_mm || std::abs(steps) > 1e9)
    throw NotSupportedError(fmt::format(
        "not supported yet: rolling with influence coefficients from '{}' (C=9) needs a rolling "
        "step of a whole number of elements: δq·{} = {} mm is {} elements of {} mm",
        t.source, axis == 'x' ? "cos χ" : "sin χ", shift_mm, shift_mm / h_mm, h_mm));
  return static_cast<int>(steps);
}

}  // namespace

Kernel table_kernel(Component c, const Grid& grid, const CombinedMaterial& material,
                    double shift_x_mm, double shift_y_mm) {
  const Table& t = *material.table;
  if (std::abs(grid.dx - t.dx_mm) > kTableElementTolerance_mm ||
      std::abs(grid.dy - t.dy_mm) > kTableElementTolerance_mm)
    throw ProblemError(
        fmt::format("influence coefficient file '{}': its elements DXFILE, DYFILE = {}, {} mm "
                    "differ from the grid's DX, DY = {}, {} mm (by more than {} mm)",
                    t.source, t.dx_mm, t.dy_mm, grid.dx, grid.dy, kTableElementTolerance_mm));
  const int sx = whole_steps(shift_x_mm, grid.dx, 'x', t);
  const int sy = whole_steps(shift_y_mm, grid.dy, 'y', t);
  const Table::Component tc = table_component(c);
  Kernel k(grid.mx, grid.my);
  for (int diy = -(grid.my - 1); diy <= grid.my - 1; ++diy)
    for (int dix = -(grid.mx - 1); dix <= grid.mx - 1; ++dix)
      k.at(dix, diy) = t.at(tc, dix + sx, diy + sy) / material.g;
  return k;
}

}  // namespace rollcontact::elastic
