// Body 2 (z < 0) is handled in its own mirrored frame z' = −z, where it is again a half-space
// z' ≥ 0: the tractions acting on it are −(px, py, pn) in global components, i.e. (−px, −py)
// tangentially and the compressive pressure +pn along +z'. Results are mirrored back with
// R = diag(1, 1, −1): u = R u', σ = R σ' R.

#include "post/subsurface.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <memory>

#include "post/half_space_response.hpp"
#include "post/nodal_loads.hpp"
#include "post/stress_invariants.hpp"
#include "post/subsurface_lattice.hpp"
#include "post/subsurface_points.hpp"

namespace rollcontact::post {

namespace {

/// Relative margin for a new extreme: exact ties (e.g. the constant surface stress under a
/// uniform load, evaluated 1e-9 element sizes deep) keep the first point in x, y, z order
/// instead of a round-off winner, as in CONTACT's reports.
constexpr double kTieMargin = 1e-6;

class ExtremeTracker {
 public:
  enum class Kind { Max, Min, AbsMax };
  ExtremeTracker(SubsurfaceExtreme& target, Kind kind) : target_(target), kind_(kind) {}

  void offer(double v, double x, double y, double z) {
    const double key = kind_ == Kind::Max ? v : kind_ == Kind::Min ? -v : std::abs(v);
    if (first_ || key > best_ + kTieMargin * std::abs(best_)) {
      first_ = false;
      best_ = key;
      target_ = {v, x, y, z};
    }
  }

 private:
  SubsurfaceExtreme& target_;
  Kind kind_;
  bool first_ = true;
  double best_ = 0.0;
};

void resize_fields(SubsurfaceResult& r) {
  const std::size_t n = r.size();
  for (auto* f : {&r.ux, &r.uy, &r.uz, &r.sighyd, &r.sigvm, &r.sigtr, &r.sig1, &r.sig2, &r.sig3,
                  &r.sxx, &r.sxy, &r.sxz, &r.syy, &r.syz, &r.szz}) {
    f->assign(n, 0.0);
  }
}

/// The raw fields (displacements, stress tensor) of one point from its corner sums; body 2
/// (z < 0) in its mirrored frame: tangential loads opposite, results mirrored back.
void set_point(SubsurfaceResult& r, std::size_t k, const LatticeFields* lattice, std::size_t at,
               const NodalLoads* loads, double x, double y, double depth, double g, double nu,
               bool body1) {
  const double flip = body1 ? 1.0 : -1.0;  // R = diag(1, 1, flip)
  std::array<double, kFieldCount> f{};
  if (lattice != nullptr) {
    for (std::size_t o = 0; o < kFieldCount; ++o) f[o] = (*lattice)[o][at];
  } else {
    CornerSums s = loads->sums(x, y, depth);
    if (!body1) {
      for (std::size_t c = 0; c < kCornerCount; ++c) {
        s.x[c] = -s.x[c];
        s.y[c] = -s.y[c];
      }
    }
    f = fields_of(response_from_sums(s, depth, g, nu));
  }
  r.ux[k] = f[kUx];
  r.uy[k] = f[kUy];
  r.uz[k] = flip * f[kUz];
  r.sxx[k] = f[kSxx];
  r.sxy[k] = f[kSxy];
  r.sxz[k] = flip * f[kSxz];
  r.syy[k] = f[kSyy];
  r.syz[k] = flip * f[kSyz];
  r.szz[k] = f[kSzz];
}

/// Element indices of centre coordinates (ISUBS 1-3, 5-7); empty when a coordinate is not a
/// centre of `n` elements from `lo` at step `h` (ISUBS 9).
std::vector<int> centre_indices(const std::vector<double>& c, double lo, double h, int n) {
  std::vector<int> idx;
  for (double v : c) {
    const double u = (v - lo) / h - 0.5;
    const long i = std::lround(u);
    if (i < 0 || i >= n || std::abs(u - static_cast<double>(i)) > 1e-9) return {};
    idx.push_back(static_cast<int>(i));
  }
  return idx;
}

/// The FFT lattice pays off when the direct sum would evaluate many more corners than the
/// lattice's offset table per depth holds (its 30 transforms cost about as much again).
bool lattice_pays_off(std::size_t points_per_depth, std::size_t loaded_nodes, const Grid& grid) {
  return static_cast<double>(points_per_depth) * static_cast<double>(loaded_nodes) >
         16.0 * 4.0 * static_cast<double>(grid.size());
}

SubsurfaceResult evaluate_block(const model::SubsurfaceBlock& block, const Solution& sol,
                                const model::Bodies& bodies, const NodalLoads& loads,
                                std::unique_ptr<SubsurfaceLattice>& lattice) {
  SubsurfaceResult r;
  PointLists pts = block_points(block, sol.grid);
  r.x = std::move(pts.x);
  r.y = std::move(pts.y);
  r.z = std::move(pts.z);
  resize_fields(r);
  const Grid& grid = sol.grid;
  const std::vector<int> ix = centre_indices(r.x, grid.xl, grid.dx, grid.mx);
  const std::vector<int> iy = centre_indices(r.y, grid.yl, grid.dy, grid.my);
  const bool on_lattice = !r.x.empty() && !r.y.empty() && ix.size() == r.x.size() &&
                          iy.size() == r.y.size() &&
                          lattice_pays_off(r.x.size() * r.y.size(), loads.node_count(), grid);
  if (on_lattice && !lattice)
    lattice = std::make_unique<SubsurfaceLattice>(grid, sol.px, sol.py, sol.pn);
  LatticeFields fields;

  std::size_t k = 0;
  for (double z : r.z) {
    const bool body1 = z >= 0.0;
    const double depth = loads.effective_depth(std::abs(z));
    const double g = body1 ? bodies.body1.shear_modulus_N_mm2 : bodies.body2.shear_modulus_N_mm2;
    const double nu = body1 ? bodies.body1.poisson_ratio : bodies.body2.poisson_ratio;
    if (on_lattice) lattice->evaluate(depth, g, nu, body1 ? 1.0 : -1.0, fields);
    for (std::size_t j = 0; j < r.y.size(); ++j)
      for (std::size_t i = 0; i < r.x.size(); ++i) {
        const std::size_t at = on_lattice ? grid.index(ix[i], iy[j]) : 0;
        set_point(r, k++, on_lattice ? &fields : nullptr, at, &loads, r.x[i], r.y[j], depth, g, nu,
                  body1);
      }
  }

  using Kind = ExtremeTracker::Kind;
  ExtremeTracker t_hyd(r.absmax_sighyd, Kind::AbsMax), t_vm(r.max_sigvm, Kind::Max),
      t_tr(r.max_sigtr, Kind::Max), t_s1(r.max_sig1, Kind::Max), t_s3(r.min_sig3, Kind::Min),
      t_xx(r.absmax_sxx, Kind::AbsMax), t_yy(r.absmax_syy, Kind::AbsMax),
      t_zz(r.absmax_szz, Kind::AbsMax);
  k = 0;
  for (double z : r.z)
    for (double y : r.y)
      for (double x : r.x) {
        const Matrix3 st{{{r.sxx[k], r.sxy[k], r.sxz[k]},
                          {r.sxy[k], r.syy[k], r.syz[k]},
                          {r.sxz[k], r.syz[k], r.szz[k]}}};
        const StressInvariants inv = stress_invariants(st);
        r.sighyd[k] = inv.hydrostatic;
        r.sigvm[k] = inv.von_mises;
        r.sigtr[k] = inv.tresca;
        r.sig1[k] = inv.principal[0];
        r.sig2[k] = inv.principal[1];
        r.sig3[k] = inv.principal[2];
        t_hyd.offer(r.sighyd[k], x, y, z);
        t_vm.offer(r.sigvm[k], x, y, z);
        t_tr.offer(r.sigtr[k], x, y, z);
        t_s1.offer(r.sig1[k], x, y, z);
        t_s3.offer(r.sig3[k], x, y, z);
        t_xx.offer(r.sxx[k], x, y, z);
        t_yy.offer(r.syy[k], x, y, z);
        t_zz.offer(r.szz[k], x, y, z);
        ++k;
      }
  return r;
}

}  // namespace

std::vector<SubsurfaceResult> compute_subsurface(const std::vector<model::SubsurfaceBlock>& blocks,
                                                 const model::Bodies& bodies,
                                                 const Solution& solution) {
  std::vector<SubsurfaceResult> out;
  if (blocks.empty()) return out;
  const NodalLoads loads(solution.grid, solution.px, solution.py, solution.pn);
  std::unique_ptr<SubsurfaceLattice> lattice;  // made once, for the blocks that use it
  out.reserve(blocks.size());
  for (const model::SubsurfaceBlock& b : blocks)
    out.push_back(evaluate_block(b, solution, bodies, loads, lattice));
  return out;
}

}  // namespace rollcontact::post
