// Ceres fit of rig parameters through the stiff simulation; the Jacobian is a forward difference
// in the scaled parameters (log for positive physical constants).

#include "diagnose/diagnose_fit.hpp"

#include <ceres/ceres.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <thread>

#include "core/error.hpp"
#include "diagnose/candidate.hpp"

namespace rheomag::diagnose {

namespace {

double to_internal(const ParamDef& d, double v) {
  return d.log_scale ? std::log(v / d.nominal) : v / d.typical;
}
double to_value(const ParamDef& d, double z) {
  return d.log_scale ? d.nominal * std::exp(z) : z * d.typical;
}

/// Residuals (model - measured) / output scale on the masked samples, as a Ceres cost. Its one
/// parameter block holds the free parameters (internal units); held ones keep their start value.
class SimulationCost : public ceres::CostFunction {
 public:
  SimulationCost(const DiagnosisModel& model, const std::vector<const Candidate*>& effects,
                 const std::vector<ParamDef>& layout, const std::vector<bool>& mask, double scale,
                 int threads, std::vector<std::size_t> free, std::vector<double> start)
      : model_(model),
        effects_(effects),
        layout_(layout),
        free_(std::move(free)),
        start_(std::move(start)),
        scale_(scale),
        threads_(threads) {
    const auto n = model.measured().size();
    for (std::size_t k = 0; k < n; ++k)
      if (mask.empty() || mask[k]) index_.push_back(k);
    set_num_residuals(static_cast<int>(index_.size()));
    mutable_parameter_block_sizes()->push_back(static_cast<int>(free_.size()));
  }

  /// Residual vector at free internal parameters zf; false if the simulation fails.
  bool residuals_at(const double* zf, double* r) const {
    std::vector<double> z = start_;
    for (std::size_t c = 0; c < free_.size(); ++c) z[free_[c]] = zf[c];
    std::vector<double> values(layout_.size());
    for (std::size_t j = 0; j < layout_.size(); ++j) values[j] = to_value(layout_[j], z[j]);
    std::vector<double> y;
    try {
      y = model_.predict(effects_, values);
    } catch (const std::exception&) {
      return false;
    }
    const auto& m = model_.measured();
    for (std::size_t i = 0; i < index_.size(); ++i) {
      r[i] = (y[index_[i]] - m[index_[i]]) / scale_;
      if (!std::isfinite(r[i])) return false;
    }
    return true;
  }

  bool Evaluate(double const* const* parameters, double* residuals,
                double** jacobians) const override {
    const double* z = parameters[0];
    if (!residuals_at(z, residuals)) return false;
    if (jacobians && jacobians[0]) {
      // One simulation per column; the columns are independent and share the threads.
      const std::size_t p = free_.size();
      const std::size_t workers = std::min<std::size_t>(std::max<std::size_t>(threads_, 1), p);
      std::vector<char> ok(p, 1);
      auto columns = [&](std::size_t first) {
        for (std::size_t j = first; j < p; j += workers)
          ok[j] = jacobian_column(z, residuals, j, jacobians[0]);
      };
      std::vector<std::thread> pool;
      for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(columns, w);
      columns(0);
      for (auto& t : pool) t.join();
      if (std::find(ok.begin(), ok.end(), 0) != ok.end()) return false;
    }
    return true;
  }

  /// Forward (or, where the model fails, backward) difference column j of the Jacobian.
  bool jacobian_column(const double* z, const double* residuals, std::size_t j,
                       double* jacobian) const {
    const std::size_t p = free_.size(), m = index_.size();
    std::vector<double> zz(z, z + p), r1(m);
    const double h = 1e-4;
    zz[j] = z[j] + h;
    double sign = 1.0;
    if (!residuals_at(zz.data(), r1.data())) {
      zz[j] = z[j] - h;
      sign = -1.0;
      if (!residuals_at(zz.data(), r1.data())) return false;
    }
    for (std::size_t i = 0; i < m; ++i) jacobian[i * p + j] = sign * (r1[i] - residuals[i]) / h;
    return true;
  }

 private:
  const DiagnosisModel& model_;
  std::vector<const Candidate*> effects_;
  std::vector<ParamDef> layout_;
  std::vector<std::size_t> free_;  ///< layout indices of the free parameters
  std::vector<double> start_;      ///< internal values of all parameters (held ones used)
  std::vector<std::size_t> index_;
  double scale_;
  int threads_ = 1;
};

double output_scale(const std::vector<double>& y) {
  double mean = 0.0;
  for (double v : y) mean += v;
  mean /= static_cast<double>(y.size());
  double s = 0.0;
  for (double v : y) s += (v - mean) * (v - mean);
  return std::max(std::sqrt(s / static_cast<double>(y.size())), 1e-300);
}

}  // namespace

double masked_sse(const std::vector<double>& measured, const std::vector<double>& prediction,
                  const std::vector<bool>& mask) {
  double s = 0.0;
  for (std::size_t k = 0; k < measured.size(); ++k)
    if (mask.empty() || mask[k]) s += (prediction[k] - measured[k]) * (prediction[k] - measured[k]);
  return s;
}

ModelFit fit_model(const DiagnosisModel& model, const std::vector<const Candidate*>& effects,
                   const std::vector<double>& start, const FitSettings& settings) {
  ModelFit fit;
  fit.effects = effects;
  fit.layout = model.layout(effects);
  const std::size_t p = fit.layout.size();
  if (start.size() != p) throw InputError("diagnose: internal parameter count mismatch");
  const auto sign_free = [](ParamDef& size) {
    size.log_scale = false;
    size.typical = size.nominal;
    size.lower = -size.upper;
  };
  if (settings.signed_last_size && !effects.empty())
    sign_free(fit.layout[p - effects.back()->params(model).size()]);
  if (settings.signed_linear_sizes) {
    std::size_t first = model.static_params().size();
    for (const Candidate* c : effects) {
      if (c->linear_in_size(model)) sign_free(fit.layout[first]);
      first += c->params(model).size();
    }
  }
  std::vector<double> z(p), lo(p), hi(p);
  for (std::size_t j = 0; j < p; ++j) {
    const auto& d = fit.layout[j];
    lo[j] = to_internal(d, d.lower);
    hi[j] = to_internal(d, d.upper);
    z[j] = std::clamp(to_internal(d, std::clamp(start[j], d.lower, d.upper)), lo[j], hi[j]);
  }
  const double scale = output_scale(model.measured());
  std::vector<std::size_t> free;
  for (std::size_t j = 0; j < p; ++j)
    if (!(j < settings.fixed.size() && settings.fixed[j])) free.push_back(j);
  const std::size_t nf = free.size();
  std::vector<double> zf(nf);
  for (std::size_t c = 0; c < nf; ++c) zf[c] = z[free[c]];
  auto* cost = new SimulationCost(model, effects, fit.layout, settings.mask, scale,
                                  settings.threads, free, z);
  ceres::Problem problem;
  problem.AddResidualBlock(cost, nullptr, zf.data());
  for (std::size_t c = 0; c < nf; ++c) {
    problem.SetParameterLowerBound(zf.data(), static_cast<int>(c), lo[free[c]]);
    problem.SetParameterUpperBound(zf.data(), static_cast<int>(c), hi[free[c]]);
  }
  ceres::Solver::Options options;
  options.minimizer_type = ceres::TRUST_REGION;
  options.trust_region_strategy_type = ceres::LEVENBERG_MARQUARDT;
  options.linear_solver_type = ceres::DENSE_QR;
  options.max_num_iterations = settings.max_iterations;
  options.function_tolerance = 1e-7;
  options.parameter_tolerance = 1e-7;
  options.logging_type = ceres::SILENT;
  options.num_threads = 1;
  // Every parameter is bounded, so Ceres would follow each step with a projected line search
  // whose trial points each cost a Jacobian (one simulation per parameter) - ten and more per
  // iteration once a parameter sits at its bound. Unless asked for, the clamped step alone.
  if (!settings.projected_line_search) options.max_num_line_search_step_size_iterations = 0;
  ceres::Solver::Summary summary;
  if (nf > 0) ceres::Solve(options, &problem, &summary);
  fit.converged = nf == 0 || summary.termination_type == ceres::CONVERGENCE;
  for (std::size_t c = 0; c < nf; ++c) z[free[c]] = zf[c];

  fit.values.resize(p);
  for (std::size_t j = 0; j < p; ++j) fit.values[j] = to_value(fit.layout[j], z[j]);
  try {
    fit.prediction = model.predict(effects, fit.values);
  } catch (const std::exception& e) {
    throw ConvergenceError(std::string("diagnose: the model cannot be simulated: ") + e.what());
  }
  fit.sse = masked_sse(model.measured(), fit.prediction, settings.mask);
  fit.samples =
      settings.mask.empty()
          ? model.measured().size()
          : static_cast<std::size_t>(std::count(settings.mask.begin(), settings.mask.end(), true));

  // Standard errors from the Jacobian at the optimum: cov = s^2 (J^T J)^-1 in internal units,
  // over the free parameters that are not at a bound and add something independent.
  fit.standard_errors.assign(p, std::numeric_limits<double>::quiet_NaN());
  const int m = cost->num_residuals();
  std::vector<double> r(m), jac(static_cast<std::size_t>(m) * nf);
  const double* params[] = {zf.data()};
  double* jacs[] = {jac.data()};
  if (settings.standard_errors && nf > 0 && m > static_cast<int>(nf) &&
      cost->Evaluate(params, r.data(), jacs)) {
    Eigen::Map<Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>> J(
        jac.data(), m, static_cast<int>(nf));
    std::vector<int> interior;  // columns of J
    for (std::size_t c = 0; c < nf; ++c) {
      const std::size_t j = free[c];
      const double margin = 1e-6 * std::max(hi[j] - lo[j], 1e-12);
      if (z[j] > lo[j] + margin && z[j] < hi[j] - margin &&
          J.col(static_cast<int>(c)).squaredNorm() > 0.0)
        interior.push_back(static_cast<int>(c));
    }
    // Columns beyond the numerical rank of a column-pivoted QR are not identified: infinite
    // standard error; the others' come from the rest.
    Eigen::MatrixXd Ji(m, static_cast<int>(interior.size()));
    for (std::size_t c = 0; c < interior.size(); ++c)
      Ji.col(static_cast<int>(c)) = J.col(interior[c]);
    const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Ji);
    std::vector<int> kept;  // columns of J
    for (int c = 0; c < static_cast<int>(interior.size()); ++c) {
      bool independent = false;
      for (int i = 0; i < static_cast<int>(qr.rank()); ++i)
        if (qr.colsPermutation().indices()(i) == c) independent = true;
      const int col = interior[static_cast<std::size_t>(c)];
      if (independent)
        kept.push_back(col);
      else
        fit.standard_errors[free[static_cast<std::size_t>(col)]] =
            std::numeric_limits<double>::infinity();
    }
    if (!kept.empty()) {
      Eigen::MatrixXd Jk(m, static_cast<int>(kept.size()));
      for (std::size_t c = 0; c < kept.size(); ++c) Jk.col(static_cast<int>(c)) = J.col(kept[c]);
      const double s2 =
          fit.sse / (scale * scale) / static_cast<double>(m - static_cast<int>(kept.size()));
      const Eigen::MatrixXd cov = s2 * (Jk.transpose() * Jk).inverse();
      for (std::size_t c = 0; c < kept.size(); ++c) {
        const std::size_t j = free[static_cast<std::size_t>(kept[c])];
        const double sz = std::sqrt(std::max(cov(static_cast<int>(c), static_cast<int>(c)), 0.0));
        fit.standard_errors[j] =
            fit.layout[j].log_scale ? fit.values[j] * sz : fit.layout[j].typical * sz;
      }
    }
  }
  return fit;
}

std::vector<double> grid_search(const DiagnosisModel& model,
                                const std::vector<const Candidate*>& effects,
                                std::vector<double> start, std::size_t j,
                                const std::vector<double>& grid, double* best_sse, int threads,
                                bool scan_delay) {
  std::vector<double> sse(grid.size(), std::numeric_limits<double>::infinity());
  std::vector<double> delay(grid.size(), 0.0);
  const std::size_t jd = model.delay_index();
  const std::size_t workers = std::min<std::size_t>(std::max(threads, 1), grid.size());
  auto score = [&](std::size_t first) {
    auto values = start;
    if (scan_delay) values[jd] = 0.0;
    for (std::size_t g = first; g < grid.size(); g += workers) {
      values[j] = grid[g];
      try {
        const auto y = model.predict(effects, values);
        if (scan_delay)
          delay[g] = model.best_delay(y, values, sse[g]);
        else
          sse[g] = masked_sse(model.measured(), y, {});
      } catch (const std::exception&) {
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w) pool.emplace_back(score, w);
  score(0);
  for (auto& t : pool) t.join();
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t g = 0; g < grid.size(); ++g)
    if (sse[g] < best) {
      best = sse[g];
      start[j] = grid[g];
      if (scan_delay) start[jd] = delay[g];
    }
  if (best_sse) *best_sse = best;
  return start;
}

std::vector<double> grid_start(const DiagnosisModel& model,
                               const std::vector<const Candidate*>& effects,
                               std::vector<double> start, double* best_sse, int threads,
                               bool scan_delay, const std::vector<double>& extra) {
  const auto layout = model.layout(effects);
  const std::size_t j = layout.size() - effects.back()->params(model).size();
  const auto& d = layout[j];
  std::vector<double> grid;
  for (double v = d.lower * 3.0; v <= d.upper; v *= 10.0) grid.push_back(v);
  grid.insert(grid.end(), extra.begin(), extra.end());
  return grid_search(model, effects, std::move(start), j, grid, best_sse, threads, scan_delay);
}

}  // namespace rheomag::diagnose
