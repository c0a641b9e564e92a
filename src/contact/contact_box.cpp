#include "contact/contact_box.hpp"

#include <algorithm>

namespace rollcontact::contact {

namespace {

/// [lo, lo + size) with size = hi − lo + 1 plus a free element each side, rounded up to a
/// multiple of 8 and clamped to n; lo moved so that the range lies inside [0, n).
void widen(int& lo, int& size, int hi, int n) {
  constexpr int multiple = 8;
  lo = std::max(lo - 1, 0);
  hi = std::min(hi + 1, n - 1);
  size = std::min(n, (hi - lo + 1 + multiple - 1) / multiple * multiple);
  lo = std::min(lo, n - size);
}

}  // namespace

std::optional<ContactBox> contact_box(const Grid& grid, const std::vector<char>& contact,
                                      double max_fraction) {
  int ix_lo = grid.mx, ix_hi = -1, iy_lo = grid.my, iy_hi = -1;
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix)
      if (contact[grid.index(ix, iy)]) {
        ix_lo = std::min(ix_lo, ix);
        ix_hi = std::max(ix_hi, ix);
        iy_lo = std::min(iy_lo, iy);
        iy_hi = std::max(iy_hi, iy);
      }
  if (ix_hi < 0) return std::nullopt;
  ContactBox box;
  box.ix0 = ix_lo;
  box.iy0 = iy_lo;
  widen(box.ix0, box.grid.mx, ix_hi, grid.mx);
  widen(box.iy0, box.grid.my, iy_hi, grid.my);
  if (static_cast<double>(box.grid.size()) > max_fraction * static_cast<double>(grid.size()))
    return std::nullopt;
  box.grid.dx = grid.dx;
  box.grid.dy = grid.dy;
  box.grid.xl = grid.xl + box.ix0 * grid.dx;
  box.grid.yl = grid.yl + box.iy0 * grid.dy;
  return box;
}

std::optional<ContactBox> interpenetration_box(const Grid& grid, const std::vector<double>& h,
                                               double pen, double max_fraction) {
  std::vector<char> inside(h.size());
  for (std::size_t i = 0; i < h.size(); ++i) inside[i] = h[i] < pen;
  return contact_box(grid, inside, max_fraction);
}

bool zero_outside(const std::vector<double>& full, const Grid& grid, const ContactBox& box) {
  for (int iy = 0; iy < grid.my; ++iy)
    for (int ix = 0; ix < grid.mx; ++ix)
      if (!box.contains(ix, iy) && full[grid.index(ix, iy)] != 0.0) return false;
  return true;
}

tangential::TangentialSystem restrict_to_box(const tangential::TangentialSystem& sys,
                                             const ContactBox& box,
                                             const tangential::TangentialOperator& a) {
  tangential::TangentialSystem out;
  out.grid = box.grid;
  out.contact = restrict_to_box(sys.contact, sys.grid, box);
  out.bound = restrict_to_box(sys.bound, sys.grid, box);
  out.bx = restrict_to_box(sys.bx, sys.grid, box);
  out.by = restrict_to_box(sys.by, sys.grid, box);
  out.a = a;
  out.chi = sys.chi;
  return out;
}

tangential::TangentialResult expand_from_box(const tangential::TangentialResult& r,
                                             const Grid& grid, const ContactBox& box) {
  tangential::TangentialResult out = tangential::no_tractions(grid.size());
  for (int iy = 0; iy < box.grid.my; ++iy)
    for (int ix = 0; ix < box.grid.mx; ++ix) {
      const std::size_t b = box.grid.index(ix, iy), f = grid.index(box.ix0 + ix, box.iy0 + iy);
      out.px[f] = r.px[b];
      out.py[f] = r.py[b];
      out.sx[f] = r.sx[b];
      out.sy[f] = r.sy[b];
      out.state[f] = r.state[b];
    }
  out.iterations = r.iterations;
  out.residual = r.residual;
  out.converged = r.converged;
  out.message = r.message;
  return out;
}

}  // namespace rollcontact::contact
