#include "contact/previous_fields.hpp"

#include <algorithm>
#include <cmath>

namespace rollcontact::contact {

/// The offset of `grid` in `old`; `shift_x`, `shift_y` [mm]: how far this grid's coordinate
/// origin lies from the older one's in the sequence's frame. None when the element sizes
/// differ.
std::optional<ElementOffset> element_offset(const Grid& old, const Grid& grid, double shift_x,
                                            double shift_y) {
  if (std::abs(old.dx - grid.dx) > 1e-6 * grid.dx || std::abs(old.dy - grid.dy) > 1e-6 * grid.dy)
    return std::nullopt;
  return ElementOffset{std::lround((grid.xl + shift_x - old.xl) / grid.dx),
                       std::lround((grid.yl + shift_y - old.yl) / grid.dy)};
}

/// `shift_x`, `shift_y` [mm]: how far this grid's coordinate origin lies from the previous one's
/// in the sequence's common frame (model::SequenceLink::origin_*).
PreviousFields map_previous(const Solution* prev, const Grid& grid, double shift_x, double shift_y,
                            FieldsToMap what) {
  PreviousFields out;
  const std::size_t n = grid.size();
  out.pn.assign(n, 0.0);
  out.covered.assign(n, 0);
  if (what.tractions) {
    out.px.assign(n, 0.0);
    out.py.assign(n, 0.0);
  }
  if (what.displacements) {
    out.ux.assign(n, 0.0);
    out.uy.assign(n, 0.0);
  }
  if (what.slips) {
    out.sx.assign(n, 0.0);
    out.sy.assign(n, 0.0);
  }
  if (prev == nullptr || prev->pn.empty()) return out;
  out.veloc = prev->kinematics.veloc;
  const bool has_mu = prev->mu.size() == prev->grid.size();
  if (has_mu) out.mu.assign(n, -1.0);  // -1: not known here (μ_static)
  const bool has_plastic = prev->plastic_accumulated.size() == prev->grid.size();
  if (has_plastic) {
    out.plastic.x.assign(n, 0.0);
    out.plastic.y.assign(n, 0.0);
    out.plastic.accumulated.assign(n, 0.0);
  }
  const Grid& old = prev->grid;
  const std::optional<ElementOffset> offset = element_offset(old, grid, shift_x, shift_y);
  if (!offset) return out;
  for_each_overlap(old, grid, *offset, [&](std::size_t i, std::size_t j) {
    out.covered[i] = 1;
    out.pn[i] = prev->pn[j];
    if (what.tractions) {
      out.px[i] = prev->px[j];
      out.py[i] = prev->py[j];
    }
    if (what.displacements && prev->ux.size() == old.size()) {
      out.ux[i] = prev->ux[j];
      out.uy[i] = prev->uy[j];
    }
    if (what.slips && prev->sx.size() == old.size()) {
      out.sx[i] = prev->sx[j];
      out.sy[i] = prev->sy[j];
    }
    if (has_mu) out.mu[i] = prev->mu[j];
    if (has_plastic) {
      out.plastic.x[i] = prev->plastic_x[j];
      out.plastic.y[i] = prev->plastic_y[j];
      out.plastic.accumulated[i] = prev->plastic_accumulated[j];
    }
  });
  out.present = true;
  return out;
}

/// `f` on grid `old` mapped onto `grid` as map_previous() does; 0 where `old` does not reach.
Field map_field(const Field& f, const Grid& old, const Grid& grid, double shift_x, double shift_y) {
  Field out(grid.size(), 0.0);
  const std::optional<ElementOffset> offset = element_offset(old, grid, shift_x, shift_y);
  if (f.size() != old.size() || !offset) return out;
  for_each_overlap(old, grid, *offset, [&](std::size_t i, std::size_t j) { out[i] = f[j]; });
  return out;
}

/// SequenceLink::new_step: the start 2·last − before of the tractions and pressures where both
/// grids reach (pressures not below 0), the last elsewhere. Only the fields a start uses.
void extrapolate_start(PreviousFields& last, const PreviousFields& before) {
  if (!last.present || !before.present) return;
  for (std::size_t i = 0; i < last.px.size(); ++i) {
    if (!last.covered[i] || !before.covered[i]) continue;
    last.px[i] = 2.0 * last.px[i] - before.px[i];
    last.py[i] = 2.0 * last.py[i] - before.py[i];
    last.pn[i] = std::max(0.0, 2.0 * last.pn[i] - before.pn[i]);
  }
}
}  // namespace rollcontact::contact
