// The Krylov solvers of the semismooth Newton iteration on small systems with known solutions.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "core/krylov.hpp"

namespace rollcontact::core {
namespace {

// 1-D operator −u'' + c·u' (central differences), n unknowns, Dirichlet ends: symmetric positive
// definite for c = 0, non-symmetric otherwise.
LinearMap convection_diffusion(double c) {
  return [c](const std::vector<double>& x, std::vector<double>& y) {
    const std::size_t n = x.size();
    y.assign(n, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      const double left = i > 0 ? x[i - 1] : 0.0, right = i + 1 < n ? x[i + 1] : 0.0;
      y[i] = 2.0 * x[i] - left - right + 0.5 * c * (right - left);
    }
  };
}

const LinearMap jacobi = [](const std::vector<double>& r, std::vector<double>& z) {
  z.resize(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) z[i] = 0.5 * r[i];
};

double relative_residual(const LinearMap& a, const std::vector<double>& b,
                         const std::vector<double>& x) {
  std::vector<double> ax;
  a(x, ax);
  double r = 0.0, nb = 0.0;
  for (std::size_t i = 0; i < b.size(); ++i) {
    r += (b[i] - ax[i]) * (b[i] - ax[i]);
    nb += b[i] * b[i];
  }
  return std::sqrt(r / nb);
}

std::vector<double> rhs(std::size_t n) {
  std::vector<double> b(n);
  for (std::size_t i = 0; i < n; ++i) b[i] = std::sin(0.37 * static_cast<double>(i)) + 0.1;
  return b;
}

TEST(Krylov, ConjugateGradientsSolveAnSpdSystemInAtMostNSteps) {
  const LinearMap a = convection_diffusion(0.0);
  const std::vector<double> b = rhs(50);
  std::vector<double> x;
  const KrylovResult r = solve_pcg(a, jacobi, b, x, 1e-10, 200);
  EXPECT_TRUE(r.converged);
  EXPECT_LE(r.iterations, 50);  // exact arithmetic: at most n steps
  EXPECT_LT(relative_residual(a, b, x), 1e-8);
}

TEST(Krylov, ConjugateGradientsReportEachStepToTheObserver) {
  // The semismooth Newton iteration accumulates A·x from the observer: Σ α·(A·d) over the
  // steps, with A·d the operator's last result when the observer runs. Check that contract.
  const LinearMap base = convection_diffusion(0.0);
  std::vector<double> last_ad;
  const LinearMap a = [&](const std::vector<double>& d, std::vector<double>& y) {
    base(d, y);
    last_ad = y;
  };
  const std::vector<double> b = rhs(60);
  std::vector<double> ax_accumulated(b.size(), 0.0), x;
  int steps = 0;
  const StepObserver observer = [&](double alpha) {
    ++steps;
    for (std::size_t i = 0; i < b.size(); ++i) ax_accumulated[i] += alpha * last_ad[i];
  };
  // Like the Newton iteration's, this preconditioner reuses the operator's scratch: the
  // observer must run before it.
  const LinearMap m = [&](const std::vector<double>& r, std::vector<double>& z) {
    jacobi(r, z);
    last_ad.assign(r.size(), 1e300);
  };
  const KrylovResult r = solve_pcg(a, m, b, x, 1e-3, 200, observer);
  EXPECT_TRUE(r.converged);
  EXPECT_EQ(steps, r.iterations);
  std::vector<double> ax;
  base(x, ax);
  for (std::size_t i = 0; i < b.size(); ++i) EXPECT_NEAR(ax_accumulated[i], ax[i], 1e-12);
}

TEST(Krylov, ConjugateGradientsStopAtTheRequestedTolerance) {
  const LinearMap a = convection_diffusion(0.0);
  const std::vector<double> b = rhs(400);
  std::vector<double> x;
  const KrylovResult loose = solve_pcg(a, jacobi, b, x, 1e-1, 1000);
  const KrylovResult tight = solve_pcg(a, jacobi, b, x, 1e-8, 1000);
  EXPECT_TRUE(loose.converged);
  EXPECT_TRUE(tight.converged);
  EXPECT_LT(loose.iterations, tight.iterations);
  const KrylovResult capped = solve_pcg(a, jacobi, b, x, 1e-12, 5);
  EXPECT_FALSE(capped.converged);
  EXPECT_EQ(capped.iterations, 5);
}

TEST(Krylov, GmresSolvesANonSymmetricSystemWithAndWithoutRestarts) {
  const LinearMap a = convection_diffusion(0.8);
  const std::vector<double> b = rhs(60);
  for (int restart : {80, 15}) {
    std::vector<double> x;
    const KrylovResult r = solve_gmres(a, jacobi, b, x, 1e-10, 2000, restart);
    EXPECT_TRUE(r.converged) << "restart " << restart;
    EXPECT_LT(relative_residual(a, b, x), 1e-9) << "restart " << restart;
  }
}

TEST(Krylov, GmresReportsItsDirectionsToTheObserver) {
  // The steady-rolling line search takes A·x as the combination of the A·z_j GMRES made: keep
  // each operator result when `applied` runs, combine them with the coefficients `combined`
  // gives, over restarts too.
  const std::vector<double> b = rhs(60);
  for (int restart : {80, 15}) {
    std::vector<double> last_ax;  // the operator's last result
    const LinearMap base = convection_diffusion(0.8);
    const LinearMap a = [&](const std::vector<double>& x, std::vector<double>& y) {
      base(x, y);
      last_ax = y;
    };
    std::vector<std::vector<double>> kept;
    std::vector<double> ax(b.size(), 0.0);
    const auto keep = [&](std::size_t j) {
      if (kept.size() <= j) kept.resize(j + 1);
      kept[j] = last_ax;
    };
    const auto combine = [&](const std::vector<double>& y, std::size_t count) {
      for (std::size_t j = 0; j < count; ++j)
        for (std::size_t i = 0; i < ax.size(); ++i) ax[i] += y[j] * kept[j][i];
    };
    const GmresObserver observer{keep, combine};
    std::vector<double> x;
    const KrylovResult r = solve_gmres(a, jacobi, b, x, 1e-10, 2000, restart, &observer);
    ASSERT_TRUE(r.converged) << "restart " << restart;
    std::vector<double> direct;
    base(x, direct);
    double diff = 0.0, size = 0.0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      diff = std::max(diff, std::abs(ax[i] - direct[i]));
      size = std::max(size, std::abs(direct[i]));
    }
    EXPECT_LT(diff, 1e-10 * size) << "restart " << restart;
  }
}

TEST(Krylov, ZeroRightHandSideGivesZero) {
  std::vector<double> x{1.0, 2.0};
  EXPECT_TRUE(solve_pcg(convection_diffusion(0.0), jacobi, {0.0, 0.0}, x, 1e-8, 10).converged);
  EXPECT_EQ(x, (std::vector<double>{0.0, 0.0}));
  EXPECT_TRUE(solve_gmres(convection_diffusion(1.0), jacobi, {0.0, 0.0}, x, 1e-8, 10).converged);
  EXPECT_EQ(x, (std::vector<double>{0.0, 0.0}));
}

}  // namespace
}  // namespace rollcontact::core
