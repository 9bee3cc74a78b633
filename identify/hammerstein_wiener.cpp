#include "identify/hammerstein_wiener.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <unsupported/Eigen/Polynomials>
#include <vector>

#include "core/error.hpp"
#include "identify/least_squares.hpp"
#include "identify/output_error.hpp"

namespace rheomag::identify {

double PiecewiseLinear::operator()(double v) const {
  const std::ptrdiff_t n = x.size();
  const double* begin = x.data();
  std::ptrdiff_t i = std::upper_bound(begin, begin + n, v) - begin - 1;
  i = std::clamp<std::ptrdiff_t>(i, 0, n - 2);
  const double t = (v - x(i)) / (x(i + 1) - x(i));
  return y(i) + t * (y(i + 1) - y(i));
}

namespace {

double spread(const Eigen::VectorXd& v) {
  const double s = std::sqrt((v.array() - v.mean()).square().mean());
  return s > 0.0 ? s : 1.0;
}

/// Breakpoints at evenly spaced quantiles of v (duplicates nudged apart).
Eigen::VectorXd quantile_breakpoints(const Eigen::VectorXd& v, int count) {
  std::vector<double> sorted(v.data(), v.data() + v.size());
  std::sort(sorted.begin(), sorted.end());
  Eigen::VectorXd x(count);
  for (int i = 0; i < count; ++i) {
    const double q = static_cast<double>(i) / (count - 1);
    x(i) = sorted[static_cast<std::size_t>(std::lround(q * (sorted.size() - 1)))];
  }
  const double step = std::max(1e-6, 1e-3 * (sorted.back() - sorted.front()));
  for (int i = 1; i < count; ++i) x(i) = std::max(x(i), x(i - 1) + step);
  return x;
}

bool stable_denominator(const Eigen::VectorXd& f) {
  if (f.size() == 0) return true;
  if (f.size() == 1) return std::abs(f(0)) < 1.0;
  Eigen::VectorXd coeffs(f.size() + 1);
  for (std::ptrdiff_t i = 0; i < f.size(); ++i) coeffs(i) = f(f.size() - 1 - i);
  coeffs(f.size()) = 1.0;
  Eigen::PolynomialSolver<double, Eigen::Dynamic> solver(coeffs);
  return (solver.roots().array().abs() < 1.0).all();
}

/// The standardised model output for blocks (f, B, F, g) on standardised input u.
Eigen::VectorXd hw_output(const PiecewiseLinear& in, const Eigen::VectorXd& b,
                          const Eigen::VectorXd& f, int nk, const PiecewiseLinear& out,
                          const Eigen::VectorXd& u) {
  Eigen::VectorXd v(u.size());
  for (std::ptrdiff_t k = 0; k < u.size(); ++k) v(k) = in(u(k));
  const Eigen::VectorXd w = DiscreteOe{f, b, nk}.simulate(v);
  Eigen::VectorXd y(u.size());
  for (std::ptrdiff_t k = 0; k < u.size(); ++k) y(k) = out(w(k));
  return y;
}

}  // namespace

HwModel::HwModel(HwOptions options, PiecewiseLinear input_map, Eigen::VectorXd b, Eigen::VectorXd f,
                 PiecewiseLinear output_map, double u_mean, double u_scale, double y_mean,
                 double y_scale)
    : options_(options),
      input_map_(std::move(input_map)),
      b_(std::move(b)),
      f_(std::move(f)),
      output_map_(std::move(output_map)),
      u_mean_(u_mean),
      u_scale_(u_scale),
      y_mean_(y_mean),
      y_scale_(y_scale) {}

std::string HwModel::name() const {
  return "hw:" + std::to_string(options_.nb) + "," + std::to_string(options_.nf) + "," +
         std::to_string(options_.nk);
}

std::vector<NamedValue> HwModel::params() const {
  std::vector<NamedValue> out{{"nb", options_.nb}, {"nf", options_.nf},
                              {"nk", options_.nk}, {"breakpoints", options_.breakpoints},
                              {"u_mean", u_mean_}, {"u_scale", u_scale_},
                              {"y_mean", y_mean_}, {"y_scale", y_scale_}};
  for (std::ptrdiff_t i = 0; i < b_.size(); ++i) out.emplace_back(numbered("b", i + 1), b_(i));
  for (std::ptrdiff_t i = 0; i < f_.size(); ++i) out.emplace_back(numbered("f", i + 1), f_(i));
  for (std::ptrdiff_t i = 0; i < input_map_.x.size(); ++i) {
    out.emplace_back(numbered("input_x", i + 1), input_map_.x(i));
    out.emplace_back(numbered("input_y", i + 1), input_map_.y(i));
  }
  for (std::ptrdiff_t i = 0; i < output_map_.x.size(); ++i) {
    out.emplace_back(numbered("output_x", i + 1), output_map_.x(i));
    out.emplace_back(numbered("output_y", i + 1), output_map_.y(i));
  }
  return out;
}

Eigen::VectorXd HwModel::run(const IoData& data, EvalMode /*mode*/) const {
  if (data.inputs() != 1) throw InputError("hw models take exactly one drive column");
  const Eigen::VectorXd u = (data.u.col(0).array() - u_mean_) / u_scale_;
  return (hw_output(input_map_, b_, f_, options_.nk, output_map_, u).array() * y_scale_ + y_mean_)
      .matrix();
}

HwModel fit_hw(const IoData& data, const HwOptions& options) {
  const HwOptions& o = options;
  if (o.nb < 1 || o.nf < 0 || o.nk < 0 || o.breakpoints < 2)
    throw InputError("hw needs nb >= 1, nf >= 0, nk >= 0 and at least 2 breakpoints");
  if (data.inputs() != 1)
    throw InputError("hw models take exactly one drive column (got " +
                     std::to_string(data.inputs()) + ")");
  const int parameters = o.nb + o.nf + 2 * o.breakpoints;
  if (data.size() < 10 * parameters)
    throw InputError("too few samples (" + std::to_string(data.size()) + ") for hw with " +
                     std::to_string(parameters) + " parameters");
  const double u_mean = data.u.col(0).mean(), u_scale = spread(data.u.col(0));
  const double y_mean = data.y.mean(), y_scale = spread(data.y);
  const Eigen::VectorXd u = (data.u.col(0).array() - u_mean) / u_scale;
  const Eigen::VectorXd y = (data.y.array() - y_mean) / y_scale;

  // Start: identity nonlinearities around the SRIV linear OE block.
  const DiscreteOe oe = fit_oe_sriv(u, y, o.nb, o.nf, o.nk);
  const Eigen::VectorXd in_x = quantile_breakpoints(u, o.breakpoints);
  const Eigen::VectorXd out_x = quantile_breakpoints(oe.simulate(u), o.breakpoints);
  Eigen::VectorXd x0(parameters);
  x0 << in_x, oe.b, stabilise(oe.f, 0.98), out_x;  // poles kept off the unit circle

  const auto unpack = [&](const Eigen::VectorXd& x, PiecewiseLinear& in, Eigen::VectorXd& b,
                          Eigen::VectorXd& f, PiecewiseLinear& out) {
    in = {in_x, x.head(o.breakpoints)};
    b = x.segment(o.breakpoints, o.nb);
    f = x.segment(o.breakpoints + o.nb, o.nf);
    out = {out_x, x.tail(o.breakpoints)};
  };
  const ResidualFunction residual = [&](const Eigen::VectorXd& x, Eigen::VectorXd& r) {
    PiecewiseLinear in, out;
    Eigen::VectorXd b, f;
    unpack(x, in, b, f, out);
    if (!stable_denominator(f)) return false;
    r = y - hw_output(in, b, f, o.nk, out, u);
    return true;
  };
  const LeastSquaresResult lm = minimise_residual(residual, x0, y.size(), 100);
  PiecewiseLinear in, out;
  Eigen::VectorXd b, f;
  unpack(lm.x, in, b, f, out);
  if (!stable_denominator(f)) throw ConvergenceError("hw fit ended on an unstable linear block");
  return HwModel(o, in, b, f, out, u_mean, u_scale, y_mean, y_scale);
}

}  // namespace rheomag::identify
