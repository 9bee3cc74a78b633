#include "identify/narx.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "core/error.hpp"

namespace rheomag::identify {

namespace {

double monomial_value(const Monomial& m, const Eigen::VectorXd& phi) {
  double v = 1.0;
  for (int i : m) v *= phi(i);
  return v;
}

Eigen::MatrixXd candidate_matrix(const Eigen::MatrixXd& phi, const std::vector<Monomial>& terms) {
  Eigen::MatrixXd p(phi.rows(), static_cast<std::ptrdiff_t>(terms.size()));
  for (std::ptrdiff_t r = 0; r < phi.rows(); ++r) {
    const Eigen::VectorXd row = phi.row(r).transpose();
    for (std::size_t t = 0; t < terms.size(); ++t) p(r, t) = monomial_value(terms[t], row);
  }
  return p;
}

std::string term_name(const Monomial& m, const LagOrders& orders, std::ptrdiff_t inputs) {
  if (m.empty()) return "const";
  std::string s;
  for (int i : m) {
    if (!s.empty()) s += "*";
    if (i < orders.na) {
      s += numbered("y(k-", i + 1) + ")";
    } else {
      const int j = (i - orders.na) / orders.nb, lag = (i - orders.na) % orders.nb + orders.nk;
      s += (inputs > 1 ? numbered("u", j + 1) : std::string("u")) + numbered("(k-", lag) + ")";
    }
  }
  return s;
}

}  // namespace

std::vector<Monomial> all_monomials(int variables, int degree) {
  std::vector<Monomial> out{Monomial{}};
  std::vector<Monomial> layer{Monomial{}};
  for (int d = 1; d <= degree; ++d) {
    std::vector<Monomial> next;
    for (const auto& m : layer)
      for (int v = m.empty() ? 0 : m.back(); v < variables; ++v) {
        Monomial grown = m;
        grown.push_back(v);
        next.push_back(grown);
      }
    out.insert(out.end(), next.begin(), next.end());
    layer = std::move(next);
  }
  return out;
}

std::vector<int> frols_order(const Eigen::MatrixXd& p, const Eigen::VectorXd& y, int max_terms) {
  const std::ptrdiff_t m = p.cols();
  Eigen::MatrixXd w = p;  // candidates, orthogonalised against the selected ones as we go
  std::vector<bool> used(m, false);
  std::vector<int> order;
  const double yy = y.squaredNorm();
  for (int step = 0; step < std::min<std::ptrdiff_t>(max_terms, m); ++step) {
    int best = -1;
    double best_err = -1.0;
    for (std::ptrdiff_t c = 0; c < m; ++c) {
      if (used[c]) continue;
      const double ww = w.col(c).squaredNorm();
      if (ww <= 1e-12 * std::max(1.0, p.col(c).squaredNorm())) continue;  // dependent
      const double wy = w.col(c).dot(y);
      const double err = wy * wy / (ww * yy);
      if (err > best_err) {
        best_err = err;
        best = static_cast<int>(c);
      }
    }
    if (best < 0) break;
    used[best] = true;
    order.push_back(best);
    const Eigen::VectorXd q = w.col(best) / w.col(best).norm();
    for (std::ptrdiff_t c = 0; c < m; ++c)
      if (!used[c]) w.col(c) -= q * q.dot(w.col(c));
  }
  return order;
}

NarxModel::NarxModel(NarxOptions options, std::vector<Monomial> terms, Eigen::VectorXd coefficients,
                     Standardisation scaling)
    : options_(options),
      terms_(std::move(terms)),
      coefficients_(std::move(coefficients)),
      scaling_(std::move(scaling)) {}

std::string NarxModel::name() const {
  const auto& o = options_.orders;
  return "narx:" + std::to_string(o.na) + "," + std::to_string(o.nb) + "," + std::to_string(o.nk) +
         "," + std::to_string(options_.degree);
}

std::vector<NamedValue> NarxModel::params() const {
  std::vector<NamedValue> out{{"na", options_.orders.na},
                              {"nb", options_.orders.nb},
                              {"nk", options_.orders.nk},
                              {"degree", options_.degree},
                              {"terms", static_cast<double>(terms_.size())},
                              {"y_mean", scaling_.y_mean},
                              {"y_scale", scaling_.y_scale}};
  for (std::ptrdiff_t j = 0; j < scaling_.u_mean.size(); ++j) {
    out.emplace_back(numbered("u", j + 1) + "_mean", scaling_.u_mean(j));
    out.emplace_back(numbered("u", j + 1) + "_scale", scaling_.u_scale(j));
  }
  for (std::size_t t = 0; t < terms_.size(); ++t)
    out.emplace_back(term_name(terms_[t], options_.orders, scaling_.u_mean.size()),
                     coefficients_(t));
  return out;
}

Eigen::VectorXd NarxModel::run(const IoData& data, EvalMode mode) const {
  const IoData scaled = scaling_.apply(data, "narx");
  const auto f = [this](const Eigen::VectorXd& phi) {
    double v = 0.0;
    for (std::size_t t = 0; t < terms_.size(); ++t)
      v += coefficients_(t) * monomial_value(terms_[t], phi);
    return v;
  };
  return scaling_.restore(run_regression_model(scaled, options_.orders, f, mode));
}

NarxModel fit_narx(const IoData& data, const NarxOptions& options) {
  const LagOrders& o = options.orders;
  if (o.na < 0 || o.nb < 1 || o.nk < 0 || options.degree < 1 || options.degree > 4)
    throw InputError("narx needs na >= 0, nb >= 1, nk >= 0 and degree 1..4");
  if (data.size() > 0 && (data.y.array() == data.y(0)).all()) {
    std::ostringstream message;
    message.precision(12);
    message << "narx: the output is constant (" << data.y(0) << " on all " << data.size()
            << " samples); there is nothing to identify";
    throw InputError(message.str());
  }
  const Standardisation scaling = Standardisation::of(data);
  const IoData scaled = scaling.apply(data, "narx");
  const std::vector<Monomial> candidates = all_monomials(o.size(data.inputs()), options.degree);

  // Term order and count chosen on the first 3/4, judged by free run on the last 1/4.
  const std::ptrdiff_t n = scaled.size();
  const std::ptrdiff_t split = (3 * n) / 4;
  if (split - o.max_lag() <= static_cast<std::ptrdiff_t>(
                                 std::min<std::size_t>(candidates.size(), options.max_terms)) ||
      n - split <= 2 * o.max_lag())
    throw InputError("too few samples (" + std::to_string(n) + ") for " +
                     std::to_string(candidates.size()) + " candidate narx terms");
  const IoData fit_part = slice(scaled, 0, split);
  const IoData check_part = slice(scaled, split, n);
  Eigen::MatrixXd phi;
  Eigen::VectorXd target;
  regressor_matrix(fit_part, o, phi, target);
  Eigen::MatrixXd p = candidate_matrix(phi, candidates);
  std::vector<int> order = frols_order(p, target, options.max_terms);
  if (order.empty())
    throw InputError(
        "narx: no candidate term is independent of the others and explains the "
        "output (rank-deficient regressors); nothing to fit");
  std::size_t best_count = 1;
  double best_error = std::numeric_limits<double>::infinity();
  Standardisation identity;
  identity.u_mean = Eigen::VectorXd::Zero(data.inputs());
  identity.u_scale = Eigen::VectorXd::Ones(data.inputs());
  for (std::size_t count = 1; count <= order.size(); ++count) {
    std::vector<Monomial> terms;
    Eigen::MatrixXd sub(p.rows(), static_cast<std::ptrdiff_t>(count));
    for (std::size_t t = 0; t < count; ++t) {
      terms.push_back(candidates[order[t]]);
      sub.col(t) = p.col(order[t]);
    }
    const Eigen::VectorXd coef = sub.colPivHouseholderQr().solve(target);
    const NarxModel trial(options, terms, coef, identity);  // on already standardised data
    const Eigen::VectorXd sim = trial.run(check_part, EvalMode::simulation);
    const double error = (sim - check_part.y).tail(check_part.size() - o.max_lag()).squaredNorm();
    if (error < best_error) {
      best_error = error;
      best_count = count;
    }
  }
  // Refit on all training samples with the chosen number of terms.
  regressor_matrix(scaled, o, phi, target);
  p = candidate_matrix(phi, candidates);
  order = frols_order(p, target, static_cast<int>(best_count));
  if (order.empty())
    throw InputError("narx: the regressors of the whole record are rank-deficient; nothing to fit");
  std::vector<Monomial> terms;
  Eigen::MatrixXd sub(p.rows(), static_cast<std::ptrdiff_t>(order.size()));
  for (std::size_t t = 0; t < order.size(); ++t) {
    terms.push_back(candidates[order[t]]);
    sub.col(t) = p.col(order[t]);
  }
  const Eigen::VectorXd coef = sub.colPivHouseholderQr().solve(target);
  return NarxModel(options, std::move(terms), coef, scaling);
}

NarxModel fit_narx_lag_search(const IoData& data, const std::vector<LagOrders>& candidates,
                              int degree) {
  if (candidates.empty()) throw InputError("narx lag search needs at least one candidate");
  const std::ptrdiff_t split = (3 * data.size()) / 4;
  const IoData fit_part = slice(data, 0, split), check_part = slice(data, split, data.size());
  NarxOptions best;
  double best_error = std::numeric_limits<double>::infinity();
  for (const auto& orders : candidates) {
    NarxOptions options;
    options.orders = orders;
    options.degree = degree;
    const NarxModel trial = fit_narx(fit_part, options);
    const Eigen::VectorXd sim = trial.run(check_part, EvalMode::simulation);
    const std::ptrdiff_t skip = orders.max_lag();
    const double error = (sim - check_part.y).tail(check_part.size() - skip).squaredNorm() /
                         static_cast<double>(check_part.size() - skip);
    if (error < best_error) {
      best_error = error;
      best = options;
    }
  }
  return fit_narx(data, best);
}

}  // namespace rheomag::identify
