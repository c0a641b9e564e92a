#include "wheelrail/vertical_force.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

namespace rollcontact::wheelrail {

namespace {

/// Power-law model through the patches of a sample: F_z(z) and dF_z/dz.
struct PowerLaw {
  std::vector<double> z0, c, f;  ///< start of contact, C_i, (cos δ + f_s sin δ)·C_i factor
  std::vector<double> cosd;
  double spring = 0.0;  ///< massless rail, N=0: + spring·z [N/mm]

  explicit PowerLaw(const HeightSample& s, double spring_N_per_mm = 0.0) : spring(spring_N_per_mm) {
    for (const PatchForceSample& p : s.patches) {
      if (!(p.pen_mm > 0.0) || !(p.fn_N > 0.0)) continue;
      const double cd = std::max(std::cos(p.delta_rad), 0.05);
      const double ci = p.fn_N / std::pow(p.pen_mm, 1.5);
      const double fs = p.fs_N / p.fn_N;
      z0.push_back(s.z_mm - p.pen_mm / cd);
      cosd.push_back(cd);
      c.push_back(ci);
      f.push_back((cd + fs * std::sin(p.delta_rad)) * ci);
    }
  }
  bool usable() const { return !z0.empty(); }
  void eval(double z, double& fz, double& dfz) const {
    fz = spring * z;
    dfz = spring;
    for (std::size_t i = 0; i < z0.size(); ++i) {
      const double pen = (z - z0[i]) * cosd[i];
      if (pen <= 0.0) continue;
      fz += f[i] * std::pow(pen, 1.5);
      dfz += 1.5 * f[i] * std::sqrt(pen) * cosd[i];
    }
  }
  /// Newton on the model for F_z = target, starting at z.
  double solve(double target, double z) const {
    double lowest = *std::min_element(z0.begin(), z0.end());
    z = std::max(z, lowest + 1e-6);
    for (int it = 0; it < 50; ++it) {
      double fz = 0.0, dfz = 0.0;
      eval(z, fz, dfz);
      if (dfz <= 0.0) {
        z = lowest + 1e-3;
        continue;
      }
      const double dz = (target - fz) / dfz;
      z = std::max(z + dz, lowest + 0.5 * (z - lowest));
      if (std::abs(target - fz) < 1e-3) break;
    }
    return z;
  }
};

double force_tolerance(const VerticalForceSettings& st) {
  const double scale = st.force_scale_N > 0.0 ? st.force_scale_N : st.target_N;
  return std::max(st.tolerance * scale, 1e-9);
}

/// Where F_z jumps across a bracket narrower than EPS, the nearer side stands as the answer (with
/// a warning) if it is within 1 % of FZ — CONTACT's own answer for mbench_a22_kpec c1 is 0.18 %
/// off — and the case is not converged otherwise.
double jump_tolerance(const VerticalForceSettings& st, double f_tol) {
  const double scale = st.force_scale_N > 0.0 ? st.force_scale_N : std::abs(st.target_N);
  return std::max(1e-2 * scale, f_tol);
}

/// A bracket [lo, hi] of z_ws [mm] with F_z + k·z − target [N] at its ends, and the elements in
/// contact at its upper end (−1: not known).
struct BracketEnds {
  double lo, hi, f_lo, f_hi;
  int contact_elements_hi = -1;
};

/// Elements in contact over a sample's patches (−1 where a patch does not say).
int contact_elements(const HeightSample& s) {
  int n = 0;
  for (const PatchForceSample& p : s.patches) {
    if (p.contact_elements < 0) return -1;
    n += p.contact_elements;
  }
  return n;
}

/// Why F_z may jump between two heights, for the message: a patch of a few elements (the grid
/// is coarse for the load: the first elements to come into contact carry a finite force) or a
/// change of the approximate pressures' shape.
std::string jump_cause(int contact_elements_hi) {
  constexpr int few = 12;
  if (contact_elements_hi >= 0 && contact_elements_hi <= few)
    return fmt::format(
        "only {} element(s) are in contact above the jump: the grid (DX, DS) is too coarse for "
        "this load, refine it",
        contact_elements_hi);
  return "the contact changes abruptly there, e.g. a second region joins a KPEC or ANALYN patch";
}

/// The end of an iteration whose bracket is narrower than EPS, the last iterate's residual
/// `residual`: converged where F_z meets the target within jump_tolerance — on the nearer side,
/// solved once more by `again(z)` (which traces it and returns its residual) if that is not the
/// last iterate —, not converged across a larger jump of F_z, whose place the result keeps.
void end_on_narrow_bracket(const VerticalForceSettings& st, double f_tol, const BracketEnds& b,
                           double residual, const std::function<double(double)>& again,
                           VerticalForceResult& res) {
  const double k = st.spring_N_per_mm;
  const double jump_tol = jump_tolerance(st, f_tol);
  const double nearer = std::min(std::abs(b.f_lo), std::abs(b.f_hi));
  if (nearer < std::abs(residual) && nearer <= jump_tol) {
    const double z = std::abs(b.f_lo) <= std::abs(b.f_hi) ? b.lo : b.hi;
    residual = again(z);
    res.z_mm = z;
    res.converged = std::isfinite(residual);
  } else if (std::abs(residual) > jump_tol) {
    // A jump of F_z larger than the target allows: no height gives FZ.
    res.message = fmt::format(
        "no z_ws gives FZ = {:.6g} N: the vertical force jumps from {:.6g} to {:.6g} N between "
        "z_ws = {:.7g} and {:.7g} mm ({})",
        st.target_N, b.f_lo + st.target_N - k * b.lo, b.f_hi + st.target_N - k * b.hi, b.lo, b.hi,
        jump_cause(b.contact_elements_hi));
    res.jump_lo_mm = b.lo;
    res.jump_hi_mm = b.hi;
    return;
  } else {
    res.converged = true;
  }
  res.message = fmt::format("stopped on |dz| < EPS with FZ - target = {:.4g} N", residual);
}

/// "δ = …°, F_s/F_n = …" of a sample's most loaded patch, for messages.
std::string main_patch_text(const HeightSample& s) {
  const auto most = std::max_element(
      s.patches.begin(), s.patches.end(),
      [](const PatchForceSample& x, const PatchForceSample& y) { return x.fn_N < y.fn_N; });
  if (most == s.patches.end() || !(most->fn_N > 0.0)) return "no loaded patch";
  return fmt::format("contact angle {:.1f} degrees, F_s/F_n = {:.3g}",
                     most->delta_rad * 180.0 / std::numbers::pi, most->fs_N / most->fn_N);
}

/// F_z of a sample's planar patches from their normal forces: Σ F_n (cos δ + r sin δ).
double planar_fz(const HeightSample& s, const std::vector<double>& ratio) {
  double fz = 0.0;
  for (std::size_t i = 0; i < s.patches.size(); ++i)
    fz += s.patches[i].fn_N *
          (std::cos(s.patches[i].delta_rad) + ratio[i] * std::sin(s.patches[i].delta_rad));
  return fz;
}

/// The height where a full solve that missed the target lands with its own tangential share,
/// from the normal estimates of the round that led to it, without solving again: each patch's
/// F_n(z) is linear through the estimate at the full solve's height and the round's nearest
/// other one, and F_z = Σ F_n (cos δ + r sin δ) with the full solve's δ and r = F_s/F_n. Only
/// where the model's own error — F_n's curvature (from the power-law model) over the step and
/// over the two estimates' distance — stays below a quarter of the force tolerance, and for
/// planar patches (whose estimates are that sum); nothing otherwise.
std::optional<double> share_corrected_height(const std::vector<HeightSample>& round,
                                             const HeightSample& full, double target_N,
                                             double spring, double f_tol) {
  const auto at_full = std::find_if(round.begin(), round.end(),
                                    [&](const HeightSample& h) { return h.z_mm == full.z_mm; });
  if (at_full == round.end()) return std::nullopt;
  const HeightSample* other = nullptr;
  for (const HeightSample& h : round)
    if (h.z_mm != full.z_mm && h.patches.size() == full.patches.size() &&
        (other == nullptr || std::abs(h.z_mm - full.z_mm) < std::abs(other->z_mm - full.z_mm)))
      other = &h;
  if (other == nullptr || at_full->patches.size() != full.patches.size() || full.patches.empty())
    return std::nullopt;
  std::vector<double> ratio, ratio_at_full, ratio_other;
  for (std::size_t i = 0; i < full.patches.size(); ++i) {
    const PatchForceSample& f = full.patches[i];
    if (!(f.fn_N > 0.0)) return std::nullopt;
    ratio.push_back(f.fs_N / f.fn_N);
    const auto r = [](const PatchForceSample& p) { return p.fn_N > 0.0 ? p.fs_N / p.fn_N : 0.0; };
    ratio_at_full.push_back(r(at_full->patches[i]));
    ratio_other.push_back(r(other->patches[i]));
  }
  // Planar patches only: the estimates' F_z is the sum above (a conformal patch's is not).
  const auto planar = [](const HeightSample& h, const std::vector<double>& r) {
    return std::abs(planar_fz(h, r) - h.fz_N) <= 1e-9 * std::max(1.0, std::abs(h.fz_N));
  };
  if (!planar(*at_full, ratio_at_full) || !planar(*other, ratio_other)) return std::nullopt;
  const double span = full.z_mm - other->z_mm;
  double slope = spring;  // dF_z/dz [N/mm]
  for (std::size_t i = 0; i < full.patches.size(); ++i) {
    const double dfn = (at_full->patches[i].fn_N - other->patches[i].fn_N) / span;
    const double d = full.patches[i].delta_rad;
    slope += dfn * (std::cos(d) + ratio[i] * std::sin(d));
  }
  if (!(slope > 0.0) || !std::isfinite(slope)) return std::nullopt;
  const double step = (target_N - full.fz_N - spring * full.z_mm) / slope;
  // The curvature of F_z(z) from the power-law model of the full solve.
  const PowerLaw model(full, spring);
  if (!model.usable()) return std::nullopt;
  const double h = std::max(std::abs(step), std::abs(span));
  double f0 = 0.0, fp = 0.0, fm = 0.0, unused = 0.0;
  model.eval(full.z_mm, f0, unused);
  model.eval(full.z_mm + h, fp, unused);
  model.eval(full.z_mm - h, fm, unused);
  const double curvature = std::abs(fp - 2.0 * f0 + fm) / (h * h);
  const double model_error = 0.5 * curvature * (step * step + std::abs(span * step));
  if (!(model_error < 0.25 * f_tol)) return std::nullopt;
  return full.z_mm + step;
}

}  // namespace

VerticalForceResult solve_vertical_force(const VerticalForceSettings& st, double start_mm,
                                         double first_guess_mm,
                                         const std::function<HeightSample(double)>& solve_at,
                                         const HeightSample* known) {
  VerticalForceResult res;
  res.trace.push_back({0, start_mm, 0.0, 0.0});
  double lo = start_mm, hi = std::numeric_limits<double>::infinity();  // F(lo) < FZ < F(hi)
  const double k = st.spring_N_per_mm;
  double f_lo = k * start_mm - st.target_N, f_hi = 0.0;  // F + k·z − target there [N]
  double z = first_guess_mm;
  double prev_z = start_mm;
  double slope_lo = 0.0, slope_hi = 0.0;  // the power-law model's dF_z/dz at the bracket's ends
  double min_secant = std::numeric_limits<double>::infinity();    // over the brackets so far
  double width_before = std::numeric_limits<double>::infinity();  // bracket two steps ago
  double width_last = width_before;
  bool have_last = false;  // the previous iterate (for the secant)
  double last_z = 0.0, last_residual = 0.0;
  // |F_z + k·z − target| of the iterate before the last one [N] (infinite until there is one).
  double older_abs_residual = std::numeric_limits<double>::infinity();
  const double f_tol = force_tolerance(st);
  HeightSample last_sample;  // the last iterate's forces, for the message
  int elements_hi = -1;      // elements in contact at the bracket's upper end
  if (known != nullptr && std::isfinite(known->fz_N) && known->z_mm > start_mm) {
    const double residual = known->fz_N + k * known->z_mm - st.target_N;
    (residual < 0.0 ? lo : hi) = known->z_mm;
    (residual < 0.0 ? f_lo : f_hi) = residual;
    if (residual >= 0.0) elements_hi = contact_elements(*known);
    have_last = true;
    last_z = known->z_mm;
    last_residual = residual;
  }
  for (int it = 1; it <= std::max(st.max_iterations, 1); ++it) {
    const HeightSample s = solve_at(z);
    last_sample = s;
    const PowerLaw model(s, k);
    double model_f = 0.0, slope = 0.0;
    if (model.usable()) model.eval(z, model_f, slope);
    res.trace.push_back({it, z, s.fz_N, slope});
    res.z_mm = z;
    if (!std::isfinite(s.fz_N)) {
      res.message = fmt::format("the vertical force is not finite at z_ws = {:g} mm", z);
      return res;
    }
    const double residual = s.fz_N + k * z - st.target_N;
    if (std::abs(residual) < f_tol) {
      res.converged = true;
      return res;
    }
    if (residual < 0.0) {
      lo = z;
      f_lo = residual;
      slope_lo = slope;
    } else {
      hi = z;
      f_hi = residual;
      slope_hi = slope;
      elements_hi = contact_elements(s);
    }
    const bool bracketed = std::isfinite(hi);
    // The z tolerance applies to the bracket once there is one, not to the last step: a steep
    // F_z(z) (mbench_a22_kpec c2, 7.7e6 N/mm) is still 80 N off after a step of EPS, and CONTACT
    // goes on there (NR 9 → 10 is a step of 8e-6 mm), while a KPEC force that jumps by 18 N
    // across a discontinuity ends as soon as the bracket around it is narrower than EPS
    // (c1: NR 3–7, all at z_ws 0.1956).
    if (bracketed ? hi - lo < st.tolerance : it > 1 && std::abs(z - prev_z) < st.tolerance) {
      if (bracketed) {
        const auto again = [&](double zz) {
          const HeightSample h = solve_at(zz);
          res.trace.push_back({it + 1, zz, h.fz_N, zz == lo ? slope_lo : slope_hi});
          return h.fz_N + k * zz - st.target_N;
        };
        end_on_narrow_bracket(st, f_tol, {lo, hi, f_lo, f_hi, elements_hi}, residual, again, res);
        return res;
      }
      // Steps below EPS without a bracket: an answer only if F_z is near the target.
      res.converged = std::abs(residual) <= jump_tolerance(st, f_tol);
      res.message = fmt::format("stopped on |dz| < EPS with FZ - target = {:.4g} N", residual);
      return res;
    }
    // F_z falling as the wheelset is lowered (the model's slope ≤ 0: the patches' normal and
    // friction forces pull the wheelset down, F_n cos δ + F_s sin δ < 0, e.g. a steep flange
    // whose friction acts downwards): the model has no answer, and the ratio F_s/F_n falls as
    // the load grows, so F_z may still turn. The approach is doubled (the model's fall-back took
    // steps of 1e-3 mm: MAXNR of them in a random case with 72 mrad yaw on the flange).
    const bool falling = !bracketed && model.usable() && !(slope > 0.0);
    double next = falling          ? 2.0 * z - start_mm + 1e-3
                  : model.usable() ? model.solve(st.target_N, z)
                                   : 2.0 * z - lo + 1e-3;
    // Near the target the secant through the last two iterates: the power-law model's slope
    // is that of Hertzian patches turned by their contact angles, and where the patches are not
    // (flange contacts, conformal ones) its Newton steps converge only linearly, each leaving
    // a fifth of the error with alternating sign (mbench right, y = 5 mm: five normal solves
    // where the secant needs three).
    if (have_last && std::abs(residual) < 0.05 * std::abs(st.target_N) && z != last_z) {
      const double secant_slope = (residual - last_residual) / (z - last_z);
      if (secant_slope > 0.0 && std::isfinite(secant_slope)) next = z - residual / secant_slope;
    }
    // Fast progress: two steps removed three quarters of the residual or more (the secant from one
    // side of the bracket converges so while the bracket's far end stays where the first step
    // overshot; breaking that off for the secant through the bracket's ends, or its bisection,
    // cost KPEC cases up to four extra solves).
    const bool converging = std::abs(residual) <= 0.25 * older_abs_residual;
    older_abs_residual = have_last ? std::abs(last_residual) : older_abs_residual;
    have_last = true;
    last_z = z;
    last_residual = residual;
    if (bracketed) {
      // Power-law proposals can creep towards one end of the bracket; when the bracket has not
      // halved in two steps, take the secant through its ends, and bisect if that is unsafe.
      // Across a jump of F_z both only nibble at one end: bisect until the bracket is narrower
      // than EPS. A jump shows as a secant slope over the bracket far beyond the model's slopes
      // at its ends and growing as the bracket shrinks (∝ 1/width); a steep but continuous
      // F_z (mbench_a22_kpec c2: 7.7e6 N/mm near the answer, 4 times the first bracket's
      // secant) keeps its secant bounded and its proposals.
      const double width = hi - lo;
      const bool stalling = width > 0.5 * width_before && !converging;
      const double secant = (f_hi - f_lo) / width;
      min_secant = std::min(min_secant, secant);
      const bool jump = secant > 4.0 * std::max(slope_lo, slope_hi) && secant > 20.0 * min_secant;
      width_before = width_last;
      width_last = width;
      if (jump) {
        next = 0.5 * (lo + hi);
      } else if (stalling || !(next > lo && next < hi)) {
        next = lo - f_lo * width / (f_hi - f_lo);
        if (!(next > lo + 0.01 * width && next < hi - 0.01 * width)) next = 0.5 * (lo + hi);
        width_before = width_last = std::numeric_limits<double>::infinity();
      }
    } else if (!(next > lo)) {
      next = z + 2.0 * (z - lo) + 1e-3;
    }
    prev_z = z;
    z = next;
  }
  res.message = fmt::format("the vertical force did not converge in MAXNR = {} iterations",
                            st.max_iterations);
  if (last_residual + st.target_N - k * last_z < 0.0 && st.target_N > 0.0)
    res.message += fmt::format(
        "; F_z stayed negative ({:.6g} N at z_ws = {:.7g} mm, {}): the contact's normal and "
        "friction forces pull the wheelset down",
        last_residual + st.target_N - k * last_z, last_z, main_patch_text(last_sample));
  return res;
}

namespace {

/// The split iteration (solve_vertical_force_split): rounds of normal-only estimates, each
/// started from and checked by a full solve. It keeps the trace, the last full solve and the
/// tangential shares F_s/F_n per patch of the last two full solves.
class SplitIteration {
 public:
  SplitIteration(const VerticalForceSettings& st, double start_mm,
                 const std::function<HeightSample(double)>& full_at,
                 const NormalOnlySolve& normal_at,
                 const std::function<HeightSample(double)>* rough_first_at)
      : st_(st),
        start_mm_(start_mm),
        full_at_(full_at),
        normal_at_(normal_at),
        rough_first_at_(rough_first_at),
        f_tol_(force_tolerance(st)),
        k_(st.spring_N_per_mm) {
    res_.trace.push_back({0, start_mm, 0.0, 0.0});
  }

  VerticalForceResult run(double first_guess_mm);

 private:
  static constexpr int kMaxRounds = 6;
  enum class Round { converged, decided, next, stop };

  /// F_z + k·z − target of the last full solve, at its height z [N].
  double residual(double z) const { return s_.fz_N + k_ * z - st_.target_N; }
  bool on_target(double z) const { return std::abs(residual(z)) < f_tol_; }
  void full(double z, bool rough = false);
  std::vector<double> ratios_at(double z) const;
  void append(const VerticalForceResult& part);
  Round round(double& z, std::vector<HeightSample>& samples);
  bool decided_at_jump(const VerticalForceResult& estimate);

  const VerticalForceSettings& st_;
  const double start_mm_;
  const std::function<HeightSample(double)>& full_at_;
  const NormalOnlySolve& normal_at_;
  const std::function<HeightSample(double)>* rough_first_at_;
  const double f_tol_, k_;
  VerticalForceResult res_;
  int iteration_ = 0;
  HeightSample s_;      ///< the last full solve
  double guess_ = 0.0;  ///< the next round's first estimate (the last full solve's model)
  // F_s/F_n per patch at the last two full solves (heights z_full_, z_before_): the ratios
  // change with z (more of the patch slides as it is loaded), and taking them fixed from the
  // last full solve made the rounds converge only linearly (each removing about three quarters
  // of the error, 8–10 solves per case on the benchmark's flange contacts); extrapolated
  // linearly in z from the last two full solves they converge in fewer rounds.
  std::vector<double> fs_ratio_, ratio_before_;
  double z_full_ = 0.0, z_before_ = 0.0;
};

void SplitIteration::append(const VerticalForceResult& part) {
  for (std::size_t j = 1; j < part.trace.size(); ++j) {
    VerticalForceStep step = part.trace[j];
    step.iteration = ++iteration_;
    res_.trace.push_back(step);
  }
}

void SplitIteration::full(double z, bool rough) {
  s_ = rough ? (*rough_first_at_)(z) : full_at_(z);
  const PowerLaw model(s_, k_);
  double model_f = 0.0, slope = 0.0;
  if (model.usable()) model.eval(z, model_f, slope);
  res_.trace.push_back({++iteration_, z, s_.fz_N, slope});
  res_.z_mm = z;
  ratio_before_ = std::move(fs_ratio_);
  z_before_ = z_full_;
  z_full_ = z;
  fs_ratio_.clear();
  for (const PatchForceSample& p : s_.patches)
    fs_ratio_.push_back(p.fn_N > 0.0 ? p.fs_N / p.fn_N : 0.0);
  // The next estimate starts from this full solve's power-law model.
  guess_ = model.usable() ? model.solve(st_.target_N, z) : z;
}

std::vector<double> SplitIteration::ratios_at(double z) const {
  if (ratio_before_.size() != fs_ratio_.size() || !(std::abs(z_full_ - z_before_) > 0.0))
    return fs_ratio_;
  std::vector<double> r = fs_ratio_;
  const double t = (z - z_full_) / (z_full_ - z_before_);
  for (std::size_t i = 0; i < r.size(); ++i) {
    // Within the range the two full solves span, and a little beyond: a change of sign of the
    // slope between rounds must not throw the estimate far away.
    r[i] += std::clamp(t, -1.0, 1.0) * (fs_ratio_[i] - ratio_before_[i]);
  }
  return r;
}

/// Estimates that end on a jump of F_z: full solves at its two sides decide when they straddle
/// the target too (the tangential share rarely moves a jump). True when that decided the result.
bool SplitIteration::decided_at_jump(const VerticalForceResult& estimate) {
  if (!std::isfinite(estimate.jump_lo_mm)) return false;
  const double lo = estimate.jump_lo_mm, hi = estimate.jump_hi_mm;
  full(lo);
  const double f_lo = residual(lo);
  full(hi);
  const double f_hi = residual(hi);
  const int elements_hi = contact_elements(s_);
  if (!(f_lo < 0.0 && f_hi >= 0.0)) return false;
  const auto again = [&](double z) {
    full(z);
    return residual(z);
  };
  end_on_narrow_bracket(st_, f_tol_, {lo, hi, f_lo, f_hi, elements_hi}, f_hi, again, res_);
  return true;
}

/// One round: normal estimates from the last full solve's model to the target with the
/// extrapolated shares, then a full solve at their height (and one at the share-corrected
/// height). `z` is where the full solves stand; `samples` receives the round's estimates.
SplitIteration::Round SplitIteration::round(double& z, std::vector<HeightSample>& samples) {
  samples.clear();
  // The full solve the round starts from is a sample of its estimates (the same pressure, and
  // F_z with its own share) where its patches are planar: the estimates' secant starts there.
  const bool full_is_estimate =
      std::abs(planar_fz(s_, fs_ratio_) - s_.fz_N) <= 1e-9 * std::max(1.0, std::abs(s_.fz_N));
  const HeightSample* known = full_is_estimate && st_.continuous_force ? &s_ : nullptr;
  const VerticalForceResult estimate = solve_vertical_force(
      st_, start_mm_, guess_,
      [&](double zz) {
        samples.push_back(normal_at_(zz, ratios_at(zz)));
        return samples.back();
      },
      known);
  append(estimate);
  if (!estimate.converged) {
    if (decided_at_jump(estimate)) return Round::decided;
    // Else the full solves start there.
    if (std::isfinite(estimate.z_mm) && estimate.z_mm > start_mm_) z = estimate.z_mm;
    return Round::stop;
  }
  if (iteration_ >= st_.max_iterations) return Round::stop;
  const bool same_height = std::abs(estimate.z_mm - z) < st_.tolerance;
  z = estimate.z_mm;
  full(z);
  if (!std::isfinite(s_.fz_N)) return Round::stop;
  if (on_target(z)) return Round::converged;
  // The full solve's own tangential share moved F_z off the target (flange contacts: tens of
  // newtons): where the round's estimates give F_n(z) precisely enough, the full solve goes
  // straight to the corrected height instead of estimating again.
  if (const std::optional<double> corrected =
          st_.continuous_force ? share_corrected_height(samples, s_, st_.target_N, k_, f_tol_)
                               : std::nullopt;
      corrected && iteration_ < st_.max_iterations) {
    z = *corrected;
    full(z);
    if (!std::isfinite(s_.fz_N)) return Round::stop;
    if (on_target(z)) return Round::converged;
  }
  // The tangential share no longer moves the estimate, but the full solve is still off: only
  // full solves can close the gap (mbench_a22_kpec c2: 60 N at the same z_ws, F_z rising by
  // 7.7e6 N/mm there).
  return same_height ? Round::stop : Round::next;
}

VerticalForceResult SplitIteration::run(double first_guess_mm) {
  double z = first_guess_mm;
  guess_ = first_guess_mm;
  // The tangential share of F_z is known only from a full solve.
  full(z, rough_first_at_ != nullptr);
  if (!std::isfinite(s_.fz_N)) {
    res_.message = fmt::format("the vertical force is not finite at z_ws = {:g} mm", z);
    return res_;
  }
  if (on_target(z)) {
    if (rough_first_at_ != nullptr) full(z);  // the answer stands only from a solve at EPS
    if (on_target(z)) {
      res_.converged = true;
      return res_;
    }
  }
  std::vector<HeightSample> round_samples;  // the normal estimates of the current round
  for (int r = 0; r < kMaxRounds; ++r) {
    const Round outcome = round(z, round_samples);
    if (outcome == Round::converged) res_.converged = true;
    if (outcome == Round::converged || outcome == Round::decided) return res_;
    if (outcome == Round::stop) break;
  }
  // Fall back on full solves from the last height.
  const VerticalForceResult plain = solve_vertical_force(st_, start_mm_, z, full_at_);
  append(plain);
  res_.z_mm = plain.z_mm;
  res_.converged = plain.converged;
  res_.message = plain.message;
  return res_;
}

}  // namespace

VerticalForceResult solve_vertical_force_split(
    const VerticalForceSettings& st, double start_mm, double first_guess_mm,
    const std::function<HeightSample(double)>& full_at, const NormalOnlySolve& normal_at,
    const std::function<HeightSample(double)>* rough_first_at) {
  return SplitIteration(st, start_mm, full_at, normal_at, rough_first_at).run(first_guess_mm);
}

}  // namespace rollcontact::wheelrail
