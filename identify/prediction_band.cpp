// Delta-method band of a grey-box prediction.

#include "identify/prediction_band.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numeric>

namespace rheomag::identify {

std::optional<PredictionBand> prediction_band(const lumped::Recording& rec, const GreyboxFit& fit) {
  const Eigen::MatrixXd& c = fit.covariance_between_recordings;
  const auto n = static_cast<Eigen::Index>(fit.params.size());
  if (c.rows() != n || c.cols() != n) return std::nullopt;
  std::vector<Eigen::Index> covered;
  for (Eigen::Index k = 0; k < n; ++k)
    if (c(k, k) > 0.0 && !fit.params[static_cast<std::size_t>(k)].at_bound) covered.push_back(k);
  const std::vector<double> y0 = simulate_greybox(rec, fit);
  const auto samples = static_cast<Eigen::Index>(y0.size());
  Eigen::MatrixXd g(samples, static_cast<Eigen::Index>(covered.size()));
  for (std::size_t j = 0; j < covered.size(); ++j) {
    GreyboxFit moved = fit;
    FittedParameter& p = moved.params[static_cast<std::size_t>(covered[j])];
    const double h = 0.1 * std::sqrt(c(covered[j], covered[j]));
    p.value += h;
    const std::vector<double> y = simulate_greybox(rec, moved);
    for (Eigen::Index i = 0; i < samples; ++i)
      g(i, static_cast<Eigen::Index>(j)) =
          (y[static_cast<std::size_t>(i)] - y0[static_cast<std::size_t>(i)]) / h;
  }
  Eigen::MatrixXd sub(static_cast<Eigen::Index>(covered.size()),
                      static_cast<Eigen::Index>(covered.size()));
  for (std::size_t a = 0; a < covered.size(); ++a)
    for (std::size_t b = 0; b < covered.size(); ++b)
      sub(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b)) = c(covered[a], covered[b]);
  const Eigen::VectorXd variance = (g * sub).cwiseProduct(g).rowwise().sum();
  const std::vector<double>& y = rec.column(fit.setup.output_column);
  const double mean = std::accumulate(y.begin(), y.end(), 0.0) / static_cast<double>(y.size());
  double spread = 0.0;
  for (double v : y) spread += (v - mean) * (v - mean);
  spread = std::sqrt(spread / static_cast<double>(y.size()));
  PredictionBand band;
  band.rms = std::sqrt(std::max(0.0, variance.mean()));
  band.percent = spread > 0.0 ? 100.0 * band.rms / spread : 0.0;
  return band;
}

}  // namespace rheomag::identify
