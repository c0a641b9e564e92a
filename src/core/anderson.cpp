#include "core/anderson.hpp"

#include <Eigen/Dense>

namespace rollcontact::core {

AndersonAccelerator::AndersonAccelerator(std::size_t n, int depth) : n_(n), depth_(depth) {}

void AndersonAccelerator::reset() {
  df_.clear();
  dg_.clear();
  has_prev_ = false;
}

void AndersonAccelerator::step(std::vector<double>& x, const std::vector<double>& g) {
  std::vector<double> f(n_);
  for (std::size_t i = 0; i < n_; ++i) f[i] = g[i] - x[i];
  if (has_prev_) {
    std::vector<double> dfk(n_), dgk(n_);
    for (std::size_t i = 0; i < n_; ++i) {
      dfk[i] = f[i] - f_prev_[i];
      dgk[i] = g[i] - g_prev_[i];
    }
    df_.push_back(std::move(dfk));
    dg_.push_back(std::move(dgk));
    if (static_cast<int>(df_.size()) > depth_) {
      df_.erase(df_.begin());
      dg_.erase(dg_.begin());
    }
  }
  f_prev_ = f;
  g_prev_ = g;
  has_prev_ = true;
  const int m = static_cast<int>(df_.size());
  if (m == 0) {
    x = g;
    return;
  }
  // γ = argmin ||f − ΔF γ||, then x = g − ΔG γ.
  Eigen::MatrixXd a(static_cast<Eigen::Index>(n_), m);
  for (int j = 0; j < m; ++j)
    for (std::size_t i = 0; i < n_; ++i) a(static_cast<Eigen::Index>(i), j) = df_[j][i];
  const Eigen::Map<const Eigen::VectorXd> fv(f.data(), static_cast<Eigen::Index>(n_));
  const Eigen::VectorXd gamma = a.colPivHouseholderQr().solve(fv);
  x = g;
  for (int j = 0; j < m; ++j)
    for (std::size_t i = 0; i < n_; ++i) x[i] -= gamma(j) * dg_[j][i];
}

}  // namespace rollcontact::core
