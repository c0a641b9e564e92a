#pragma once
// The previous case of a sequence on the current grid: its fields mapped element for element
// (same element size, integer offset; physics.md §2 "Sequences"), and the extrapolated start
// of a new step of steady rolling.

#include <cstddef>
#include <optional>
#include <vector>

#include "contact/interfacial_layer.hpp"
#include "rollcontact/grid.hpp"
#include "rollcontact/solution.hpp"

namespace rollcontact::contact {

/// Element (ix, iy) of a grid is element (ix + ox, iy + oy) of an older one.
struct ElementOffset {
  long ox = 0, oy = 0;
};
/// The offset of `grid` in `old`; `shift_x`, `shift_y` [mm]: how far this grid's coordinate
/// origin lies from the older one's in the sequence's frame. None when the element sizes
/// differ.
std::optional<ElementOffset> element_offset(const Grid& old, const Grid& grid, double shift_x,
                                            double shift_y);

/// Calls visit(i, j) for every element i of `grid` whose element j = i + offset lies in `old`.
template <class Visit>
void for_each_overlap(const Grid& old, const Grid& grid, ElementOffset offset, Visit&& visit) {
  for (int iy = 0; iy < grid.my; ++iy) {
    const long jy = iy + offset.oy;
    if (jy < 0 || jy >= old.my) continue;
    for (int ix = 0; ix < grid.mx; ++ix) {
      const long jx = ix + offset.ox;
      if (jx >= 0 && jx < old.mx)
        visit(grid.index(ix, iy), static_cast<std::size_t>(jx + old.mx * jy));
    }
  }
}

/// Fields of the previous case mapped onto the current grid (same element size, integer offset);
/// zero where the old grid did not reach (physics.md §2 "Sequences").
struct PreviousFields {
  bool present = false;
  std::vector<char> covered;  ///< 1 where the previous grid reaches
  Field px, py, pn;
  Field ux, uy;                     ///< displacements (transient Fastsim)
  Field sx, sy;                     ///< slip per δq (T=1: per step)
  Field mu;                         ///< velocity-dependent friction: μ per element (else empty)
  contact::PlasticHistory plastic;  ///< interfacial layer with plasticity (else empty)
  double veloc = 1.0;               ///< rolling velocity [mm/s] of the previous case
};

/// Which of the previous case's fields beside the pressures a case reads; those not asked for
/// stay empty (a vertical-force iteration's normal-only estimates read the pressures alone, and
/// mapping eight fields for each of them cost 2 % of a force sweep's instructions).
struct FieldsToMap {
  bool tractions = true;      ///< px, py
  bool displacements = true;  ///< ux, uy
  bool slips = true;          ///< sx, sy
};

/// `shift_x`, `shift_y` [mm]: how far this grid's coordinate origin lies from the previous one's
/// in the sequence's common frame (model::SequenceLink::origin_*).
PreviousFields map_previous(const Solution* prev, const Grid& grid, double shift_x, double shift_y,
                            FieldsToMap what = {});

/// `f` on grid `old` mapped onto `grid` as map_previous() does; 0 where `old` does not reach.
Field map_field(const Field& f, const Grid& old, const Grid& grid, double shift_x, double shift_y);

/// SequenceLink::new_step: the start 2·last − before of the tractions and pressures where both
/// grids reach (pressures not below 0), the last elsewhere. Only the fields a start uses.
void extrapolate_start(PreviousFields& last, const PreviousFields& before);

}  // namespace rollcontact::contact
