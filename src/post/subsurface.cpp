// Body 2 (z < 0) is handled in its own mirrored frame z' = −z, where it is again a half-space
// z' ≥ 0: the tractions acting on it are −(px, py, pn) in global components, i.e. (−px, −py)
// tangentially and the compressive pressure +pn along +z'. Results are mirrored back with
// R = diag(1, 1, −1): u = R u', σ = R σ' R.

#include "post/subsurface.hpp"

#include <cmath>
#include <cstddef>

#include "post/half_space_response.hpp"
#include "post/nodal_loads.hpp"
#include "post/stress_invariants.hpp"
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

SubsurfaceResult evaluate_block(const model::SubsurfaceBlock& block, const Solution& sol,
                                const model::Bodies& bodies, const NodalLoads& loads) {
  SubsurfaceResult r;
  PointLists pts = block_points(block, sol.grid);
  r.x = std::move(pts.x);
  r.y = std::move(pts.y);
  r.z = std::move(pts.z);
  resize_fields(r);

  using Kind = ExtremeTracker::Kind;
  ExtremeTracker t_hyd(r.absmax_sighyd, Kind::AbsMax), t_vm(r.max_sigvm, Kind::Max),
      t_tr(r.max_sigtr, Kind::Max), t_s1(r.max_sig1, Kind::Max), t_s3(r.min_sig3, Kind::Min),
      t_xx(r.absmax_sxx, Kind::AbsMax), t_yy(r.absmax_syy, Kind::AbsMax),
      t_zz(r.absmax_szz, Kind::AbsMax);

  std::size_t k = 0;
  for (double z : r.z) {
    const bool body1 = z >= 0.0;
    const double depth = loads.effective_depth(std::abs(z));
    const double g = body1 ? bodies.body1.shear_modulus_N_mm2 : bodies.body2.shear_modulus_N_mm2;
    const double nu = body1 ? bodies.body1.poisson_ratio : bodies.body2.poisson_ratio;
    const double flip = body1 ? 1.0 : -1.0;  // R = diag(1, 1, flip)
    for (double y : r.y) {
      for (double x : r.x) {
        CornerSums s = loads.sums(x, y, depth);
        if (!body1) {
          // Tangential tractions on body 2 are opposite; the pressure stays compressive.
          for (std::size_t c = 0; c < kCornerCount; ++c) {
            s.x[c] = -s.x[c];
            s.y[c] = -s.y[c];
          }
        }
        const HalfSpaceResponse h = response_from_sums(s, depth, g, nu);
        const Matrix3& st = h.stress;
        r.ux[k] = h.u[0];
        r.uy[k] = h.u[1];
        r.uz[k] = flip * h.u[2];
        r.sxx[k] = st[0][0];
        r.sxy[k] = st[0][1];
        r.sxz[k] = flip * st[0][2];
        r.syy[k] = st[1][1];
        r.syz[k] = flip * st[1][2];
        r.szz[k] = st[2][2];
        const StressInvariants inv = stress_invariants(st);  // invariant under R
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
    }
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
  out.reserve(blocks.size());
  for (const model::SubsurfaceBlock& b : blocks)
    out.push_back(evaluate_block(b, solution, bodies, loads));
  return out;
}

}  // namespace rollcontact::post
