#include "optimise/problem.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>

#include "core/error.hpp"

namespace rheomag::optimise {

namespace {
constexpr double kNoBound = 1e19;  // Ipopt's "infinity"
}

std::string number_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

double constraint_scale(const Constraint& c) {
  double scale = 0.0;
  if (std::isfinite(c.lower)) scale = std::max(scale, std::abs(c.lower));
  if (std::isfinite(c.upper)) scale = std::max(scale, std::abs(c.upper));
  return scale > 0.0 ? scale : 1.0;
}

double quantity_value(const design::Quantities& q, design::Quantity quantity) {
  if (!q.has(quantity))
    throw InputError("optimise: quantity \"" + design::quantity_name(quantity) +
                     "\" is not available for this case");
  return q[quantity];
}

ScaledProgram::ScaledProgram(const OptimiseSpec& spec, EvaluateDesign evaluate,
                             double objective_scale, std::vector<HistoryRow>& history)
    : spec_(spec),
      evaluate_(std::move(evaluate)),
      objective_scale_(objective_scale),
      history_(history) {}

std::vector<double> ScaledProgram::to_design(const std::vector<double>& u) const {
  std::vector<double> x(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) {
    const auto& v = spec_.variables[i];
    x[i] = v.lower + u[i] * (v.upper - v.lower);
  }
  return x;
}

std::vector<double> ScaledProgram::to_scaled(const std::vector<double>& x) const {
  std::vector<double> u(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto& v = spec_.variables[i];
    u[i] = (x[i] - v.lower) / (v.upper - v.lower);
  }
  return u;
}

const design::Quantities* ScaledProgram::at(const std::vector<double>& u,
                                            const std::string& purpose) {
  auto it = cache_.find(u);
  if (it != cache_.end()) return it->second.ok ? &it->second.q : nullptr;
  HistoryRow row;
  row.purpose = purpose;
  row.x = to_design(u);
  if (purpose != "gradient") last_centre_ = u;
  try {
    row.q = evaluate_(row.x, purpose == "gradient");
    objective_value(spec_, row.q);
    for (const auto& c : spec_.constraints) quantity_value(row.q, c.quantity);
  } catch (const std::exception& error) {
    row.ok = false;
    row.error = error.what();
  }
  history_.push_back(row);
  auto inserted = cache_.emplace(u, std::move(row)).first;
  return inserted->second.ok ? &inserted->second.q : nullptr;
}

double ScaledProgram::f(const design::Quantities& q) const {
  const double v = objective_value(spec_, q) / objective_scale_;
  return spec_.maximise ? -v : v;
}

void ScaledProgram::g(const design::Quantities& q, std::vector<double>& out) const {
  out.resize(spec_.constraints.size());
  for (std::size_t j = 0; j < spec_.constraints.size(); ++j)
    out[j] =
        quantity_value(q, spec_.constraints[j].quantity) / constraint_scale(spec_.constraints[j]);
}

bool ScaledProgram::values(const std::vector<double>& u, double& f_value,
                           std::vector<double>& g_value) {
  const design::Quantities* q = at(u, "iterate");
  if (!q) return false;
  f_value = f(*q);
  g(*q, g_value);
  return true;
}

// Central differences in u (one-sided at the bounds of [0, 1]), or forward differences from
// u itself (backward at the upper bound); objective and constraints from the same evaluations.
bool ScaledProgram::derivatives(const std::vector<double>& u, std::vector<double>& grad,
                                std::vector<double>& jacobian) {
  const std::size_t n = u.size(), m = spec_.constraints.size();
  const double h = spec_.step;
  const bool forward = spec_.differences == Differences::forward;
  // Forward differences subtract u's own evaluation, so it must be the design the neighbours
  // reuse (the last evaluated as not a neighbour); otherwise u is evaluated again first.
  std::optional<design::Quantities> centre;
  if (forward) {
    const design::Quantities* q = last_centre_ == u ? at(u, "iterate") : evaluate_centre(u);
    if (!q) return false;
    centre = *q;
  }
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<double> plus = u, minus = u;
    plus[i] = u[i] + h;
    minus[i] = u[i] - h;
    if (forward) {
      if (plus[i] <= 1.0)
        minus = u;
      else
        plus = u;
    } else {
      if (plus[i] > 1.0) plus = u;
      if (minus[i] < 0.0) minus = u;
    }
    const double width = plus[i] - minus[i];
    auto side = [&](const std::vector<double>& v) -> const design::Quantities* {
      return centre && v == u ? &*centre : at(v, "gradient");
    };
    const design::Quantities* qp = side(plus);
    if (!qp) return false;
    const design::Quantities q_plus = *qp;
    const design::Quantities* qm = side(minus);
    if (!qm) return false;
    grad[i] = (f(q_plus) - f(*qm)) / width;
    std::vector<double> g_plus, g_minus;
    g(q_plus, g_plus);
    g(*qm, g_minus);
    for (std::size_t j = 0; j < m; ++j) jacobian[j * n + i] = (g_plus[j] - g_minus[j]) / width;
  }
  return true;
}

const design::Quantities* ScaledProgram::evaluate_centre(const std::vector<double>& u) {
  cache_.erase(u);
  return at(u, "centre");
}

void ScaledProgram::seed(const std::vector<double>& x, const design::Quantities& q,
                         const std::string& purpose) {
  HistoryRow row;
  row.purpose = purpose;
  row.x = x;
  row.q = q;
  history_.push_back(row);
  cache_.emplace(to_scaled(x), std::move(row));
}

NlpResult ScaledProgram::solve(const std::vector<double>& start, const IpoptSettings& settings) {
  NlpProblem nlp;
  nlp.lower.assign(spec_.variables.size(), 0.0);
  nlp.upper.assign(spec_.variables.size(), 1.0);
  nlp.start = to_scaled(start);
  for (auto& u : nlp.start) u = std::clamp(u, 0.0, 1.0);
  for (const auto& k : spec_.constraints) {
    const double scale = constraint_scale(k);
    nlp.g_lower.push_back(std::isfinite(k.lower) ? k.lower / scale : -kNoBound);
    nlp.g_upper.push_back(std::isfinite(k.upper) ? k.upper / scale : kNoBound);
  }
  nlp.values = [this](const std::vector<double>& u, double& f_value, std::vector<double>& g_value) {
    return values(u, f_value, g_value);
  };
  nlp.derivatives = [this](const std::vector<double>& u, std::vector<double>& grad,
                           std::vector<double>& jacobian) {
    return derivatives(u, grad, jacobian);
  };
  NlpResult result = solve_nlp(nlp, settings);
  result.x = to_design(result.x);
  for (std::size_t i = 0; i < result.x.size(); ++i)
    result.x[i] = std::clamp(result.x[i], spec_.variables[i].lower, spec_.variables[i].upper);
  return result;
}

std::string history_csv(const OptimiseSpec& spec, const std::vector<HistoryRow>& rows) {
  std::ostringstream out;
  out << "evaluation,purpose";
  for (const auto& v : spec.variables) out << "," << v.key;
  for (design::Quantity q : design::all_quantities())
    out << "," << design::quantity_name(q) << " [" << design::quantity_unit(q) << "]";
  out << ",error\n";
  for (std::size_t k = 0; k < rows.size(); ++k) {
    out << k + 1 << "," << rows[k].purpose;
    for (double x : rows[k].x) out << "," << number_text(x);
    for (design::Quantity q : design::all_quantities())
      out << "," << (std::isnan(rows[k].q[q]) ? std::string() : number_text(rows[k].q[q]));
    std::string error = rows[k].error;
    for (char& ch : error)
      if (ch == ',' || ch == '\n' || ch == '"') ch = ' ';
    out << "," << error << "\n";
  }
  return out.str();
}

}  // namespace rheomag::optimise
