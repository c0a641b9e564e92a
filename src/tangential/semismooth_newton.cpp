// Semismooth Newton iteration for the frictional tangential problem (see tangential_system.hpp).
//
// Coulomb's law on every contact element is written as the fixed-point equation
//
//   F_i(p) = p_i − P_g(z_i) = 0,   z_i = p_i − r·S_i,   S = b + A·p,
//
// with P_g the projection onto the disk |p| ≤ g_i and r > 0 a scaling (1/diagonal of A).
// |z| ≤ g gives adhesion (S = 0), |z| > g slip with p = g·z/|z| opposite to S. F is piecewise
// smooth; Newton's method with its generalised Jacobian
//
//   adhesion:  (A δp)_i = −S_i
//   slip:      δp_i = a·n + β·t  (n = z/|z|, t ⟂ n),  a = g − p·n,
//              D_i β + t·(A δp)_i = −p·t/(κ r),  κ = g/|z|,  D_i = (1 − κ)/(κ r)
//
// converges superlinearly once the adhesion/slip division has settled (Hintermüller, Ito &
// Kunisch 2002; Hüeber, Stadler & Wohlmuth 2008 for Coulomb friction). The reduced system in
// the adhesion tractions and the slip angles is QᵀAQ + D: symmetric positive definite for
// shifts and transient rolling (solved by PCG), non-symmetric for steady rolling and for
// coefficients turned by a one-sided inclination correction (C=4 variants 1–3; GMRES). Both
// are preconditioned by the block-circulant approximation of A⁻¹ on the adhesion elements and
// on slip elements near the slip onset, and by the diagonal elsewhere. A backtracking line
// search on ‖F‖ globalises the iteration. Each Krylov iteration costs one FFT product.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/krylov.hpp"
#include "physics/friction_disk.hpp"
#include "tangential/tangential_system.hpp"

namespace rollcontact::tangential {

namespace {

enum class Role : char { Adhesion, Slip, Fixed };

struct ElementLinearisation {
  Role role = Role::Fixed;
  std::size_t offset = 0;     ///< first unknown in the reduced vector
  double nx = 0.0, ny = 0.0;  ///< slip: unit vector of z (tangent t = (−ny, nx))
  double d = 0.0;             ///< slip: D_i
  bool circulant = true;      ///< slip: preconditioned with the circulant (else diagonal)
  double jacobi = 0.0;        ///< slip: 1/(D_i + tᵀA_ii t)
};

class SemismoothNewton {
 public:
  SemismoothNewton(const TangentialSystem& sys, const TangentialSettings& settings)
      : sys_(sys), settings_(settings), n_(sys.grid.size()) {
    for (std::size_t i = 0; i < n_; ++i)
      if (sys.contact[i]) elements_.push_back(i);
    lin_.resize(elements_.size());
    d_[0] = sys.a.xx->at(0, 0);
    d_[1] = sys.a.xy->at(0, 0);
    d_[2] = sys.a.yx->at(0, 0);
    d_[3] = sys.a.yy->at(0, 0);
    // r decides the division: with p on the bound an element turns to adhesion when its
    // predicted slip reverses, whatever r; from adhesion it turns to slip when |p − r·S| > g,
    // where S carries the inexactness of the Krylov solve. A small r makes that test follow the
    // traction (fewest Newton steps for shifts: 31–34 products at every benchmark grid). In
    // steady rolling the adhesion front moves about one element per step along the rows;
    // 0.5 measured best there (287×323: 268, 161 and 507 products at 0.2, 0.5 and 0.8; see
    // docs/decisions.md).
    r_ = (sys.a.steady ? 0.5 : 0.03) * 2.0 / (d_[0] + d_[3]);
    for (auto* v : {&sx_, &sy_, &fx_, &fy_, &ux_, &uy_, &ax_, &ay_}) v->assign(n_, 0.0);
  }

  void run(TangentialResult& res) {
    std::vector<double>& px = res.px;
    std::vector<double>& py = res.py;
    for (std::size_t i = 0; i < n_; ++i)
      if (!sys_.contact[i]) px[i] = py[i] = 0.0;
    slip(px, py, sx_, sy_);
    int products = 1;
    const int max_products = std::max(100, 10 * settings_.max_iterations);
    std::vector<double> dpx(n_, 0.0), dpy(n_, 0.0), tx(n_), ty(n_), ts_x(n_), ts_y(n_);
    double fnorm = merit(px, py, sx_, sy_);
    int newton = 0;
    while (true) {
      const double pnorm = traction_norm(px, py);
      res.residual = pnorm > 0.0 ? fnorm / pnorm : 0.0;
      if (fnorm <= settings_.eps * pnorm || fnorm == 0.0) {
        res.converged = true;
        break;
      }
      if (newton >= max_newton || products >= max_products) {
        res.message = fmt::format(
            "semismooth Newton did not converge in {} steps and {} products (relative "
            "residual {:.3e})",
            newton, products, res.residual);
        break;
      }
      ++newton;
      // δp and A·δp for the line search (linear in the step length).
      products += newton_direction(px, py, dpx, dpy);
      double lambda = 1.0, best_lambda = 1.0, best = std::numeric_limits<double>::infinity();
      for (int trial = 0; trial < 6; ++trial, lambda *= 0.5) {
        for (std::size_t i : elements_) {
          tx[i] = px[i] + lambda * dpx[i];
          ty[i] = py[i] + lambda * dpy[i];
          ts_x[i] = sx_[i] + lambda * ax_[i];
          ts_y[i] = sy_[i] + lambda * ay_[i];
        }
        const double f = merit(tx, ty, ts_x, ts_y);
        if (f < best) {
          best = f;
          best_lambda = lambda;
        }
        if (f <= (1.0 - 1e-4 * lambda) * fnorm) break;
      }
      for (std::size_t i : elements_) {
        px[i] += best_lambda * dpx[i];
        py[i] += best_lambda * dpy[i];
        sx_[i] += best_lambda * ax_[i];
        sy_[i] += best_lambda * ay_[i];
      }
      fnorm = best;
    }
    // The feasible traction nearest to the iterate: adhesion p = z, slip p = g z/|z|.
    for (std::size_t i : elements_) {
      double zx = px[i] - r_ * sx_[i], zy = py[i] - r_ * sy_[i];
      physics::project_onto_disk(zx, zy, sys_.bound[i]);
      px[i] = zx;
      py[i] = zy;
    }
    res.iterations = products;
    if (settings_.slip_of_last_iterate)
      finalise(sys_, res, &sx_, &sy_);
    else
      finalise(sys_, res);
  }

 private:
  void slip(const std::vector<double>& px, const std::vector<double>& py, std::vector<double>& sx,
            std::vector<double>& sy) const {
    sys_.a.apply(px, py, sx, sy);
    for (std::size_t i : elements_) {
      sx[i] += sys_.bx[i];
      sy[i] += sys_.by[i];
    }
  }

  double traction_norm(const std::vector<double>& px, const std::vector<double>& py) const {
    double s = 0.0;
    for (std::size_t i : elements_) s += px[i] * px[i] + py[i] * py[i];
    return std::sqrt(s);
  }

  /// ‖F(p)‖ for the traction p with slip S.
  double merit(const std::vector<double>& px, const std::vector<double>& py,
               const std::vector<double>& sx, const std::vector<double>& sy) const {
    double s = 0.0;
    for (std::size_t i : elements_) {
      double zx = px[i] - r_ * sx[i], zy = py[i] - r_ * sy[i];
      physics::project_onto_disk(zx, zy, sys_.bound[i]);
      s += (px[i] - zx) * (px[i] - zx) + (py[i] - zy) * (py[i] - zy);
    }
    return std::sqrt(s);
  }

  /// Linearises F at p, solves the Newton system and returns δp; returns the products used.
  /// A·δp on the contact elements is left in (ax_, ay_), accumulated from the products the
  /// Krylov iteration makes anyway (A·δ0 + the same combination of A·Q·d as δp of d).
  int newton_direction(const std::vector<double>& px, const std::vector<double>& py,
                       std::vector<double>& dpx, std::vector<double>& dpy) {
    // Classification and the fixed part δ0 of δp (slip magnitudes, zero-bound elements).
    std::size_t nu = 0;
    std::fill(dpx.begin(), dpx.end(), 0.0);
    std::fill(dpy.begin(), dpy.end(), 0.0);
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const std::size_t i = elements_[k];
      ElementLinearisation& e = lin_[k];
      const double g = sys_.bound[i];
      const physics::DiskLinearisation lin =
          physics::linearise_disk_projection(px[i] - r_ * sx_[i], py[i] - r_ * sy_[i], g);
      e.offset = nu;
      if (lin.region == physics::DiskLinearisation::Region::ZeroBound) {
        e.role = Role::Fixed;
        dpx[i] = -px[i];
        dpy[i] = -py[i];
      } else if (lin.region == physics::DiskLinearisation::Region::Interior) {
        e.role = Role::Adhesion;
        nu += 2;
      } else {
        e.role = Role::Slip;
        e.nx = lin.nx;
        e.ny = lin.ny;
        const double kappa = lin.kappa;
        e.d = (1.0 - kappa) / (kappa * r_);
        const double tx = -e.ny, ty = e.nx;
        const double tat = tx * (d_[0] * tx + d_[1] * ty) + ty * (d_[2] * tx + d_[3] * ty);
        e.jacobi = 1.0 / (e.d + tat);
        e.circulant = e.d <= circulant_threshold * tat;
        const double a = g - (px[i] * e.nx + py[i] * e.ny);
        dpx[i] = a * e.nx;
        dpy[i] = a * e.ny;
        nu += 1;
      }
    }

    int products = 0;
    // Right-hand side: −S − A δ0 on adhesion, −p·t/(κr) − t·(A δ0) on slip.
    sys_.a.apply(dpx, dpy, ux_, uy_);
    ++products;
    std::vector<double> rhs(nu), y;
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const std::size_t i = elements_[k];
      const ElementLinearisation& e = lin_[k];
      if (e.role == Role::Adhesion) {
        rhs[e.offset] = -sx_[i] - ux_[i];
        rhs[e.offset + 1] = -sy_[i] - uy_[i];
      } else if (e.role == Role::Slip) {
        const double tx = -e.ny, ty = e.nx;
        const double g = sys_.bound[i];
        const double zabs = std::hypot(px[i] - r_ * sx_[i], py[i] - r_ * sy_[i]);
        rhs[e.offset] = -(px[i] * tx + py[i] * ty) * zabs / (g * r_) - (tx * ux_[i] + ty * uy_[i]);
      }
    }
    const core::LinearMap op = [&](const std::vector<double>& v, std::vector<double>& out) {
      scatter(v, fx_, fy_, false);
      sys_.a.apply(fx_, fy_, ux_, uy_);
      out.resize(nu);
      for (std::size_t k = 0; k < elements_.size(); ++k) {
        const std::size_t i = elements_[k];
        const ElementLinearisation& e = lin_[k];
        if (e.role == Role::Adhesion) {
          out[e.offset] = ux_[i];
          out[e.offset + 1] = uy_[i];
        } else if (e.role == Role::Slip) {
          out[e.offset] = -e.ny * ux_[i] + e.nx * uy_[i] + e.d * v[e.offset];
        }
      }
    };
    const core::LinearMap prec = [&](const std::vector<double>& v, std::vector<double>& out) {
      scatter(v, fx_, fy_, true);
      if (sys_.a.steady) cumulative_sum_from_leading_edge(sys_.grid, sys_.chi, fx_, fy_);
      sys_.a.preconditioner->apply(fx_.data(), fy_.data(), ux_.data(), uy_.data());
      out.resize(nu);
      for (std::size_t k = 0; k < elements_.size(); ++k) {
        const std::size_t i = elements_[k];
        const ElementLinearisation& e = lin_[k];
        if (e.role == Role::Adhesion) {
          out[e.offset] = ux_[i];
          out[e.offset + 1] = uy_[i];
        } else if (e.role == Role::Slip) {
          out[e.offset] = e.circulant ? -e.ny * ux_[i] + e.nx * uy_[i] : e.jacobi * v[e.offset];
        }
      }
    };
    const double rtol = 0.1;  // inexact Newton: 0.03 and 0.3 measured no better
    // (ux_, uy_) still hold A·δ0. A·δp = A·δ0 + A·Q·y is accumulated from the products the
    // Krylov iteration makes anyway, saving the line search one product per Newton step.
    for (std::size_t i : elements_) {
      ax_[i] = ux_[i];
      ay_[i] = uy_[i];
    }
    core::KrylovResult kr;
    if (sys_.a.symmetric) {
      // After each PCG step (ux_, uy_) hold A·Q·d of the step's direction d (the preconditioner
      // overwrites them only after the observer has run).
      const core::StepObserver accumulate = [&](double alpha) {
        for (std::size_t i : elements_) {
          ax_[i] += alpha * ux_[i];
          ay_[i] += alpha * uy_[i];
        }
      };
      kr = core::solve_pcg(op, prec, rhs, y, rtol, max_krylov, accumulate);
    } else {
      // GMRES: A·Q·z_j of each direction on the contact elements, combined as the solution is.
      const std::size_t nc = elements_.size();
      const core::GmresObserver keep{
          [&](std::size_t j) {
            if (basis_products_.size() <= j) basis_products_.resize(j + 1);
            std::vector<double>& u = basis_products_[j];
            u.resize(2 * nc);
            for (std::size_t k = 0; k < nc; ++k) {
              u[2 * k] = ux_[elements_[k]];
              u[2 * k + 1] = uy_[elements_[k]];
            }
          },
          [&](const std::vector<double>& coefficients, std::size_t count) {
            for (std::size_t j = 0; j < count; ++j) {
              const std::vector<double>& u = basis_products_[j];
              const double c = coefficients[j];
              for (std::size_t k = 0; k < nc; ++k) {
                ax_[elements_[k]] += c * u[2 * k];
                ay_[elements_[k]] += c * u[2 * k + 1];
              }
            }
          }};
      kr = core::solve_gmres(op, prec, rhs, y, rtol, max_krylov, gmres_restart, &keep);
    }
    products += kr.iterations;
    // δp = δ0 + Q y.
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const std::size_t i = elements_[k];
      const ElementLinearisation& e = lin_[k];
      if (e.role == Role::Adhesion) {
        dpx[i] = y[e.offset];
        dpy[i] = y[e.offset + 1];
      } else if (e.role == Role::Slip) {
        dpx[i] -= e.ny * y[e.offset];
        dpy[i] += e.nx * y[e.offset];
      }
    }
    return products;
  }

  /// Full-grid field of a reduced vector: adhesion (v_x, v_y), slip β·t (optionally only the
  /// slip elements preconditioned by the circulant), zero elsewhere.
  void scatter(const std::vector<double>& v, std::vector<double>& fx, std::vector<double>& fy,
               bool preconditioner) const {
    std::fill(fx.begin(), fx.end(), 0.0);
    std::fill(fy.begin(), fy.end(), 0.0);
    for (std::size_t k = 0; k < elements_.size(); ++k) {
      const std::size_t i = elements_[k];
      const ElementLinearisation& e = lin_[k];
      if (e.role == Role::Adhesion) {
        fx[i] = v[e.offset];
        fy[i] = v[e.offset + 1];
      } else if (e.role == Role::Slip && (!preconditioner || e.circulant)) {
        fx[i] = -e.ny * v[e.offset];
        fy[i] = e.nx * v[e.offset];
      }
    }
  }

  static constexpr int max_newton = 100;
  static constexpr int max_krylov = 200;
  static constexpr int gmres_restart = 40;
  // Slip elements whose regularisation D_i exceeds this fraction of tᵀA_ii t are dominated by
  // D_i and get the diagonal; the others behave like adhesion and get the circulant. Measured
  // on the benchmark patch (fine products shift / steady at 71×81, 143×163, 287×323): 1.0 gave
  // 34/27/31 and 38/46/60, 0.5 gives 33/29/27 and 35/41/47; 0.3, 0.4 and 0.7 were close to 0.5,
  // 3 and more markedly worse (steady 287×323: 1953 ms at 3 against 702 ms).
  static constexpr double circulant_threshold = 0.5;

  const TangentialSystem& sys_;
  const TangentialSettings& settings_;
  std::size_t n_;
  std::vector<std::size_t> elements_;
  std::vector<ElementLinearisation> lin_;
  double d_[4];
  double r_;
  std::vector<double> sx_, sy_, fx_, fy_, ux_, uy_, ax_, ay_;
  /// GMRES: A·Q·z_j on the contact elements (x, y interleaved) per direction of a cycle.
  std::vector<std::vector<double>> basis_products_;
};

}  // namespace

TangentialResult solve_semismooth_newton(const TangentialSystem& sys,
                                         const TangentialSettings& settings,
                                         const std::vector<double>* px0,
                                         const std::vector<double>* py0) {
  if (sys.a.preconditioner == nullptr) return solve_convex_gs(sys, settings, px0, py0);
  const std::size_t n = sys.grid.size();
  TangentialResult res;
  res.px = px0 ? *px0 : std::vector<double>(n, 0.0);
  res.py = py0 ? *py0 : std::vector<double>(n, 0.0);
  SemismoothNewton newton(sys, settings);
  newton.run(res);
  return res;
}

}  // namespace rollcontact::tangential
