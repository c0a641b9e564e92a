#pragma once
// The tangential problem on the box around the contact area instead of the whole grid.
//
// Tractions vanish outside the contact, and the solvers need the slip only on it, so the
// tangential problem restricted to any rectangle that holds the contact is the same problem:
// the influence operators are translation invariant, A·p inside the box does not depend on
// elements outside it where p = 0. Where the contact covers a small part of the potential
// contact area (a contact moving over a long grid, a small load on a generous grid) the FFT
// products on the box cost a fraction of those on the grid.

#include <optional>
#include <vector>

#include "rollcontact/grid.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::contact {

/// A rectangle of elements of a grid: element (ix, iy) of `grid` is element (ix0 + ix, iy0 + iy)
/// of the full grid; `grid` carries the box's own corner, so element centres are unchanged.
struct ContactBox {
  int ix0 = 0, iy0 = 0;
  Grid grid;

  /// True when element (ix, iy) of the full grid lies in the box.
  bool contains(int ix, int iy) const noexcept {
    return ix >= ix0 && ix < ix0 + grid.mx && iy >= iy0 && iy < iy0 + grid.my;
  }
};

/// The box around the elements in contact with one free element on each side where the grid
/// has it, its sides rounded up to multiples of 8 elements (so that a contact that moves or
/// grows a little keeps the box size, whose operators are cached), inside the grid. nullopt
/// when no element is in contact or the box would exceed `max_fraction` of the grid's elements.
std::optional<ContactBox> contact_box(const Grid& grid, const std::vector<char>& contact,
                                      double max_fraction);

/// The box around the elements where the bodies interpenetrate, h < pen [mm] (h ≥ pen and
/// excluded elements outside), as contact_box. For a prescribed approach on a half-space whose
/// influence coefficients are positive (Johnson's process, A·p ≥ 0 for p ≥ 0) the contact lies
/// inside: an element with h ≥ pen keeps a gap h − pen + A·p ≥ 0 whatever the pressure.
std::optional<ContactBox> interpenetration_box(const Grid& grid, const std::vector<double>& h,
                                               double pen, double max_fraction);

/// The entries of a full-grid field inside the box, in the box's element order.
template <class T>
std::vector<T> restrict_to_box(const std::vector<T>& full, const Grid& grid,
                               const ContactBox& box) {
  std::vector<T> out(box.grid.size());
  for (int iy = 0; iy < box.grid.my; ++iy)
    for (int ix = 0; ix < box.grid.mx; ++ix)
      out[box.grid.index(ix, iy)] = full[grid.index(box.ix0 + ix, box.iy0 + iy)];
  return out;
}

/// A field of the box on the full grid, `outside` elsewhere.
template <class T>
std::vector<T> expand_from_box(const std::vector<T>& in_box, const Grid& grid,
                               const ContactBox& box, T outside) {
  std::vector<T> out(grid.size(), outside);
  for (int iy = 0; iy < box.grid.my; ++iy)
    for (int ix = 0; ix < box.grid.mx; ++ix)
      out[grid.index(box.ix0 + ix, box.iy0 + iy)] = in_box[box.grid.index(ix, iy)];
  return out;
}

/// True when `full` vanishes outside the box (a field the box holds entirely).
bool zero_outside(const std::vector<double>& full, const Grid& grid, const ContactBox& box);

/// The system on the box with the box's operator `a` (same material, loading and step).
tangential::TangentialSystem restrict_to_box(const tangential::TangentialSystem& sys,
                                             const ContactBox& box,
                                             const tangential::TangentialOperator& a);

/// The box's result on the full grid: zero tractions and slip, Exterior, outside the box.
tangential::TangentialResult expand_from_box(const tangential::TangentialResult& r,
                                             const Grid& grid, const ContactBox& box);

}  // namespace rollcontact::contact
