#include "identify/tf_estimation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <unsupported/Eigen/MatrixFunctions>
#include <unsupported/Eigen/Polynomials>

#include "core/error.hpp"
#include "identify/least_squares.hpp"
#include "identify/output_error.hpp"

namespace rheomag::identify {

Eigen::VectorXcd ContinuousTf::pole_values() const {
  const int n = poles();
  if (n == 0) return Eigen::VectorXcd();
  Eigen::VectorXd coeffs(n + 1);  // increasing degree: a_0 .. a_{n-1}, 1
  for (int i = 0; i < n; ++i) coeffs(i) = den(n - 1 - i);
  coeffs(n) = 1.0;
  if (n == 1) {
    Eigen::VectorXcd p(1);
    p(0) = -den(0);
    return p;
  }
  Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(coeffs);
  return solver.roots();
}

bool ContinuousTf::stable() const {
  if (!den.allFinite() || !num.allFinite()) return false;
  const Eigen::VectorXcd p = pole_values();
  for (std::ptrdiff_t i = 0; i < p.size(); ++i)
    if (!(p(i).real() < 0.0)) return false;
  return true;
}

DiscreteStateSpace discretise_zoh(const ContinuousTf& g, double h) {
  const int n = g.poles();
  // Controllable canonical form: x' = A x + B u, y = C x, states x_i = d^(i-1) v / dt^(i-1).
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(n + 1, n + 1);
  for (int i = 0; i + 1 < n; ++i) m(i, i + 1) = 1.0;
  for (int i = 0; i < n; ++i) m(n - 1, i) = -g.den(n - 1 - i);
  m(n - 1, n) = 1.0;
  const Eigen::MatrixXd e = (m * h).exp();
  DiscreteStateSpace d;
  d.ad = e.topLeftCorner(n, n);
  d.bd = e.topRightCorner(n, 1);
  d.c = Eigen::RowVectorXd::Zero(n);
  for (int j = 0; j <= g.zeros(); ++j) d.c(j) = g.num(g.zeros() - j);
  return d;
}

namespace {

/// States x(k) (rows) from zero initial state.
Eigen::MatrixXd zero_state_trajectory(const DiscreteStateSpace& d, const Eigen::VectorXd& u) {
  const std::ptrdiff_t n = d.ad.rows();
  Eigen::MatrixXd x(u.size(), n);
  Eigen::VectorXd state = Eigen::VectorXd::Zero(n);
  for (std::ptrdiff_t k = 0; k < u.size(); ++k) {
    x.row(k) = state.transpose();
    state = d.ad * state + d.bd * u(k);
  }
  return x;
}

/// Rows e_1^T Ad^k: a basis of all free responses of the (observable) canonical realisation.
Eigen::MatrixXd free_response_basis(const DiscreteStateSpace& d, std::ptrdiff_t samples) {
  const std::ptrdiff_t n = d.ad.rows();
  Eigen::MatrixXd o(samples, n);
  Eigen::RowVectorXd row = Eigen::RowVectorXd::Unit(n, 0);
  for (std::ptrdiff_t k = 0; k < samples; ++k) {
    o.row(k) = row;
    row = row * d.ad;
  }
  return o;
}

/// G with its time axis rescaled to the unit `t` (coefficient of s^p times t^(np-p)).
ContinuousTf time_scaled(const ContinuousTf& g, double t) {
  ContinuousTf out = g;
  const int n = g.poles();
  for (int i = 0; i < n; ++i) out.den(i) *= std::pow(t, i + 1);  // den(i) is a_{n-1-i}
  for (int j = 0; j <= g.zeros(); ++j) out.num(j) *= std::pow(t, n - (g.zeros() - j));
  return out;
}

/// Output of g (time unit = sample) on u with the free response fitted to y by least squares.
Eigen::VectorXd simulate_with_fitted_initial_state(const ContinuousTf& g, const Eigen::VectorXd& u,
                                                   const Eigen::VectorXd& y) {
  const DiscreteStateSpace d = discretise_zoh(g, 1.0);
  const Eigen::VectorXd forced = zero_state_trajectory(d, u) * d.c.transpose();
  const Eigen::MatrixXd o = free_response_basis(d, u.size());
  const Eigen::VectorXd z = o.colPivHouseholderQr().solve(y - forced);
  return forced + o * z;
}

/// For a denominator (time unit = sample): numerator and free response by linear least squares;
/// returns the numerator and writes the residual.
Eigen::VectorXd separable_numerator(const Eigen::VectorXd& den, int nz, const Eigen::VectorXd& u,
                                    const Eigen::VectorXd& y, Eigen::VectorXd* residual) {
  const int n = static_cast<int>(den.size());
  ContinuousTf g{Eigen::VectorXd::Zero(nz + 1), den};
  const DiscreteStateSpace d = discretise_zoh(g, 1.0);
  const Eigen::MatrixXd x = zero_state_trajectory(d, u);
  Eigen::MatrixXd basis(u.size(), nz + 1 + n);
  basis.leftCols(nz + 1) = x.leftCols(nz + 1);  // y_j = response of s^j / A(s)
  basis.rightCols(n) = free_response_basis(d, u.size());
  const Eigen::VectorXd coef = basis.colPivHouseholderQr().solve(y);
  if (residual) *residual = y - basis * coef;
  Eigen::VectorXd num(nz + 1);
  for (int j = 0; j <= nz; ++j) num(nz - j) = coef(j);
  return num;
}

/// Continuous poles (time unit = sample) of a discrete model's F, s = ln z, with |z| kept in
/// [1e-3, 0.999] so that every pole is stable; real (also negative real) z give real s.
std::vector<std::complex<double>> continuous_poles(const Eigen::VectorXd& f) {
  const std::ptrdiff_t n = f.size();
  std::vector<std::complex<double>> z;
  if (n == 1) {
    z.emplace_back(-f(0));
  } else {
    Eigen::VectorXd coeffs(n + 1);
    for (std::ptrdiff_t i = 0; i < n; ++i) coeffs(i) = f(n - 1 - i);
    coeffs(n) = 1.0;
    Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(coeffs);
    for (std::ptrdiff_t i = 0; i < n; ++i) z.push_back(solver.roots()(i));
  }
  std::vector<std::complex<double>> s;
  for (auto zi : z) {
    const double r = std::clamp(std::abs(zi), 1e-3, 0.999);
    if (std::abs(zi.imag()) < 1e-9 * std::max(1.0, std::abs(zi)))
      s.emplace_back(std::log(r), 0.0);
    else
      s.emplace_back(std::log(r), std::arg(zi));
  }
  return s;
}

/// Stable-by-construction denominator: a product of quadratics s^2 + e^x0 s + e^x1 (and one
/// first-order factor s + e^x for odd np). Returns a_{np-1} .. a_0.
Eigen::VectorXd denominator_from_factors(const Eigen::VectorXd& x) {
  std::vector<double> poly{1.0};  // highest power first
  auto multiply = [&poly](const std::vector<double>& factor) {
    std::vector<double> out(poly.size() + factor.size() - 1, 0.0);
    for (std::size_t i = 0; i < poly.size(); ++i)
      for (std::size_t j = 0; j < factor.size(); ++j) out[i + j] += poly[i] * factor[j];
    poly = std::move(out);
  };
  std::ptrdiff_t i = 0;
  for (; i + 1 < x.size(); i += 2) multiply({1.0, std::exp(x(i)), std::exp(x(i + 1))});
  if (i < x.size()) multiply({1.0, std::exp(x(i))});
  Eigen::VectorXd den(x.size());
  for (std::ptrdiff_t k = 0; k < x.size(); ++k) den(k) = poly[k + 1];
  return den;
}

/// Factor parameters (see denominator_from_factors) for stable poles s: complex pairs form
/// quadratics, real poles are paired in order of speed, an odd one left over is first order.
Eigen::VectorXd factors_from_poles(std::vector<std::complex<double>> s) {
  std::vector<double> real;
  std::vector<std::complex<double>> upper;
  for (const auto& p : s) {
    if (p.imag() == 0.0)
      real.push_back(-p.real());
    else if (p.imag() > 0.0)
      upper.push_back(p);
  }
  std::sort(real.begin(), real.end());
  Eigen::VectorXd x(static_cast<std::ptrdiff_t>(s.size()));
  std::ptrdiff_t k = 0;
  for (const auto& p : upper) {
    x(k++) = std::log(-2.0 * p.real());
    x(k++) = std::log(std::norm(p));
  }
  std::size_t r = 0;
  for (; r + 1 < real.size(); r += 2) {
    x(k++) = std::log(real[r] + real[r + 1]);
    x(k++) = std::log(real[r] * real[r + 1]);
  }
  if (r < real.size()) x(k++) = std::log(real[r]);
  return x;
}

double safe_scale(const Eigen::VectorXd& v) {
  const double mean = v.mean();
  const double s = std::sqrt((v.array() - mean).square().mean());
  return s > 0.0 ? s : 1.0;
}

}  // namespace

Eigen::VectorXd simulate_tf(const ContinuousTf& g, const Eigen::VectorXd& u, double h,
                            const Eigen::VectorXd& x0) {
  const DiscreteStateSpace d = discretise_zoh(time_scaled(g, h), 1.0);
  Eigen::VectorXd state = x0.size() ? x0 : Eigen::VectorXd::Zero(g.poles());
  Eigen::VectorXd y(u.size());
  for (std::ptrdiff_t k = 0; k < u.size(); ++k) {
    y(k) = d.c.dot(state);
    state = d.ad * state + d.bd * u(k);
  }
  return y;
}

TfModel::TfModel(ContinuousTf g, double sample_time)
    : g_(std::move(g)), sample_time_(sample_time) {}

std::string TfModel::name() const {
  return "tf:" + std::to_string(g_.poles()) + "," + std::to_string(g_.zeros());
}

std::vector<NamedValue> TfModel::params() const {
  std::vector<NamedValue> out{{"np", g_.poles()}, {"nz", g_.zeros()}};
  for (int j = 0; j <= g_.zeros(); ++j) out.emplace_back(numbered("b", g_.zeros() - j), g_.num(j));
  for (int i = 0; i < g_.poles(); ++i)
    out.emplace_back(numbered("a", g_.poles() - 1 - i), g_.den(i));
  return out;
}

Eigen::VectorXd TfModel::run(const IoData& data, EvalMode /*mode*/) const {
  if (data.inputs() != 1) throw InputError("tf models take exactly one drive column");
  const ContinuousTf g = time_scaled(g_, sample_time_);
  return simulate_with_fitted_initial_state(g, data.u.col(0), data.y);
}

TfModel fit_tf(const IoData& data, int np, int nz) {
  if (np < 1 || nz < 0 || nz >= np)
    throw InputError("tf orders need np >= 1 and 0 <= nz < np (got tf:" + std::to_string(np) + "," +
                     std::to_string(nz) + ")");
  if (data.inputs() != 1)
    throw InputError("tf models take exactly one drive column (got " +
                     std::to_string(data.inputs()) + ")");
  if (data.size() < 10 * (2 * np + nz + 1))
    throw InputError("too few samples (" + std::to_string(data.size()) +
                     ") for tf:" + std::to_string(np) + "," + std::to_string(nz));
  // Work with unit-variance signals and time in samples, for conditioning.
  const double su = safe_scale(data.u.col(0)), sy = safe_scale(data.y);
  const Eigen::VectorXd u = data.u.col(0) / su, y = data.y / sy;

  // Starts: the instrumental-variable estimate (discrete SRIV OE model, poles mapped to
  // continuous time) and, as a second start, real poles spread log-evenly over 0.01-1 rad/sample.
  std::vector<Eigen::VectorXd> starts;
  starts.push_back(factors_from_poles(continuous_poles(fit_oe_sriv(u, y, np, np, 1).f)));
  {
    std::vector<std::complex<double>> spread;
    for (int i = 0; i < np; ++i)
      spread.emplace_back(-std::pow(10.0, np == 1 ? -1.0 : -2.0 + 2.0 * i / (np - 1)), 0.0);
    starts.push_back(factors_from_poles(spread));
  }

  // Levenberg-Marquardt on the simulation error over the (stable by construction) denominator
  // factors; numerator and initial state are linear and solved inside each evaluation
  // (separable least squares).
  const ResidualFunction residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    const Eigen::VectorXd den = denominator_from_factors(x);
    if (!den.allFinite() || !(den.array() > 0.0).all()) return false;
    separable_numerator(den, nz, u, y, &r);
    return true;
  };
  std::optional<LeastSquaresResult> best;
  for (const auto& x0 : starts) {
    const LeastSquaresResult lm = minimise_residual(residual, x0, y.size(), 200);
    if (!best || lm.cost < best->cost) best = lm;
  }
  const Eigen::VectorXd den = denominator_from_factors(best->x);
  ContinuousTf g{separable_numerator(den, nz, u, y, nullptr), den};
  // Positive factor coefficients make every pole stable; refuse a fit that underflowed to a
  // marginal (zero) coefficient.
  if (!(den.array() > 0.0).all() || !g.num.allFinite())
    throw ConvergenceError("tf:" + std::to_string(np) + "," + std::to_string(nz) +
                           " refinement ended on a marginally stable model (a pole at s = 0)");
  g.num *= sy / su;
  return TfModel(time_scaled(g, 1.0 / data.sample_time), data.sample_time);
}

TfModel fit_tf_auto(const IoData& data, int max_poles) {
  std::optional<TfModel> best;
  double best_score = std::numeric_limits<double>::infinity();
  for (int np = 1; np <= max_poles; ++np)
    for (int nz = 0; nz < np; ++nz) {
      try {
        TfModel model = fit_tf(data, np, nz);
        const Eigen::VectorXd e = data.y - model.run(data, EvalMode::simulation);
        const double n = static_cast<double>(e.size());
        const double score =
            n * std::log(std::max(e.squaredNorm() / n, 1e-300)) + 2.0 * (2 * np + nz + 1);
        if (score < best_score) {
          best_score = score;
          best.emplace(std::move(model));
        }
      } catch (const ConvergenceError&) {
        // an order without a stable fit is skipped
      }
    }
  if (!best)
    throw ConvergenceError("tf:auto found no stable model up to " + std::to_string(max_poles) +
                           " poles");
  return *best;
}

}  // namespace rheomag::identify
