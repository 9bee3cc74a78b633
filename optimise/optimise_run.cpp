#include "optimise/optimise_run.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <sstream>

#include "magnetostatics/report.hpp"
#include "mesh/error.hpp"
#include "optimise/optimise_case_edit.hpp"
#include "optimise/optimise_ipopt.hpp"
#include "optimise/sweep_results_file.hpp"

namespace rheomag::optimise {

namespace {

constexpr double kNoBound = 1e19;  // Ipopt's "infinity"
constexpr int kRestarts = 2;       // Ipopt restarts after a failed fresh-mesh check

std::string number_text(double v) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}

// Scale of a constraint: its largest finite bound in magnitude (1 if both are 0).
double constraint_scale(const Constraint& c) {
  double scale = 0.0;
  if (std::isfinite(c.lower)) scale = std::max(scale, std::abs(c.lower));
  if (std::isfinite(c.upper)) scale = std::max(scale, std::abs(c.upper));
  return scale > 0.0 ? scale : 1.0;
}

// Value of a quantity; InputError if the design does not provide it.
double quantity(const Quantities& q, const std::string& name) {
  auto it = q.find(name);
  if (it == q.end() || !std::isfinite(it->second))
    throw InputError("optimise: quantity \"" + name + "\" is not available for this case");
  return it->second;
}

// One evaluated design, for the history.
struct HistoryRow {
  std::string purpose;
  std::vector<double> x;
  Quantities q;
  bool ok = true;
  std::string error;
};

// The scaled program around a DesignEvaluator: u in [0, 1]^n, f = -+objective / |initial|,
// g_j = quantity_j / scale_j. Every evaluation is cached by u and recorded.
class ScaledProgram {
 public:
  ScaledProgram(DesignEvaluator& evaluator, double objective_scale)
      : e_(evaluator), spec_(evaluator.spec()), objective_scale_(objective_scale) {}

  std::vector<double> to_design(const std::vector<double>& u) const {
    std::vector<double> x(u.size());
    for (std::size_t i = 0; i < u.size(); ++i) {
      const auto& v = spec_.variables[i];
      x[i] = v.lower + u[i] * (v.upper - v.lower);
    }
    return x;
  }
  std::vector<double> to_scaled(const std::vector<double>& x) const {
    std::vector<double> u(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
      const auto& v = spec_.variables[i];
      u[i] = (x[i] - v.lower) / (v.upper - v.lower);
    }
    return u;
  }
  // Quantities at u, or nullptr if the design cannot be evaluated.
  const Quantities* at(const std::vector<double>& u, const std::string& purpose) {
    auto it = cache_.find(u);
    if (it != cache_.end()) return it->second.ok ? &it->second.q : nullptr;
    HistoryRow row;
    row.purpose = purpose;
    row.x = to_design(u);
    try {
      row.q = e_.evaluate(row.x);
      quantity(row.q, spec_.objective);
      for (const auto& c : spec_.constraints) quantity(row.q, c.quantity);
    } catch (const std::exception& error) {
      row.ok = false;
      row.error = error.what();
    }
    history_.push_back(row);
    auto inserted = cache_.emplace(u, std::move(row)).first;
    return inserted->second.ok ? &inserted->second.q : nullptr;
  }
  double f(const Quantities& q) const {
    const double v = quantity(q, spec_.objective) / objective_scale_;
    return spec_.maximise ? -v : v;
  }
  void g(const Quantities& q, std::vector<double>& out) const {
    out.resize(spec_.constraints.size());
    for (std::size_t j = 0; j < spec_.constraints.size(); ++j)
      out[j] = quantity(q, spec_.constraints[j].quantity) / constraint_scale(spec_.constraints[j]);
  }
  bool values(const std::vector<double>& u, double& f_value, std::vector<double>& g_value) {
    const Quantities* q = at(u, "iterate");
    if (!q) return false;
    f_value = f(*q);
    g(*q, g_value);
    return true;
  }
  // Central differences in u (one-sided at the bounds of [0, 1]).
  bool derivatives(const std::vector<double>& u, std::vector<double>& grad,
                   std::vector<double>& jacobian) {
    const std::size_t n = u.size(), m = spec_.constraints.size();
    const double h = spec_.step;
    for (std::size_t i = 0; i < n; ++i) {
      std::vector<double> plus = u, minus = u;
      plus[i] = u[i] + h;
      minus[i] = u[i] - h;
      if (plus[i] > 1.0) plus = u;
      if (minus[i] < 0.0) minus = u;
      const double width = plus[i] - minus[i];
      const Quantities* qp = at(plus, "gradient");
      if (!qp) return false;
      const Quantities q_plus = *qp;
      const Quantities* qm = at(minus, "gradient");
      if (!qm) return false;
      grad[i] = (f(q_plus) - f(*qm)) / width;
      std::vector<double> g_plus, g_minus;
      g(q_plus, g_plus);
      g(*qm, g_minus);
      for (std::size_t j = 0; j < m; ++j) jacobian[j * n + i] = (g_plus[j] - g_minus[j]) / width;
    }
    return true;
  }
  const std::vector<HistoryRow>& history() const { return history_; }
  /// Records an evaluation done outside the program (the start) so Ipopt does not repeat it.
  void seed(const std::vector<double>& u, const Quantities& q, const std::string& purpose) {
    HistoryRow row;
    row.purpose = purpose;
    row.x = to_design(u);
    row.q = q;
    history_.push_back(row);
    cache_.emplace(u, std::move(row));
  }
  /// Drops the cached evaluations (after the reference mesh changed).
  void forget() { cache_.clear(); }

 private:
  DesignEvaluator& e_;
  const OptimiseSpec& spec_;
  double objective_scale_;
  std::map<std::vector<double>, HistoryRow> cache_;
  std::vector<HistoryRow> history_;
};

std::string history_csv(const OptimiseSpec& spec, const std::vector<HistoryRow>& rows) {
  std::ostringstream out;
  out << "evaluation,purpose";
  for (const auto& v : spec.variables) out << "," << v.key;
  for (const auto& [name, unit] : quantity_units()) out << "," << name << " [" << unit << "]";
  out << ",error\n";
  for (std::size_t k = 0; k < rows.size(); ++k) {
    out << k + 1 << "," << rows[k].purpose;
    for (double x : rows[k].x) out << "," << number_text(x);
    for (const auto& [name, unit] : quantity_units()) {
      auto it = rows[k].q.find(name);
      out << "," << (it == rows[k].q.end() ? std::string() : number_text(it->second));
    }
    std::string error = rows[k].error;
    for (char& ch : error)
      if (ch == ',' || ch == '\n' || ch == '"') ch = ' ';
    out << "," << error << "\n";
  }
  return out.str();
}

std::string bound_text(const Constraint& c) {
  std::string text;
  if (std::isfinite(c.lower)) text += number_text(c.lower) + " <= ";
  text += c.quantity;
  if (std::isfinite(c.upper)) text += " <= " + number_text(c.upper);
  return text;
}

}  // namespace

DesignReport report_design(const OptimiseSpec& spec, const std::vector<double>& x,
                           const Quantities& quantities) {
  DesignReport report;
  report.x = x;
  report.quantities = quantities;
  report.objective = quantity(quantities, spec.objective);
  for (const auto& c : spec.constraints) {
    ConstraintStatus status;
    status.constraint = c;
    status.value = quantity(quantities, c.quantity);
    const double tolerance = kFeasibilityTolerance * constraint_scale(c);
    status.satisfied = status.value >= c.lower - tolerance && status.value <= c.upper + tolerance;
    const double near = 1e-2 * constraint_scale(c);
    status.active =
        std::abs(status.value - c.lower) <= near || std::abs(status.value - c.upper) <= near;
    report.feasible = report.feasible && status.satisfied;
    report.constraints.push_back(status);
  }
  for (std::size_t i = 0; i < spec.variables.size(); ++i) {
    const auto& v = spec.variables[i];
    const double near = 1e-3 * (v.upper - v.lower);
    if (x[i] <= v.lower + near || x[i] >= v.upper - near)
      report.variables_at_bounds.push_back(v.key);
  }
  return report;
}

OptimiseResult run_optimisation(const magnetostatics::Case& c, const OptimiseOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  OptimiseResult result;
  result.spec = read_optimise_spec(c);
  const OptimiseSpec& spec = result.spec;
  DesignEvaluator evaluator(c, spec);
  std::vector<double> x0;
  for (const auto& v : spec.variables) x0.push_back(v.initial);
  Quantities q0;
  try {
    q0 = evaluator.evaluate(x0);
  } catch (const ConvergenceError& e) {
    throw ConvergenceError(c.source.string() +
                           ": the initial design did not converge: " + e.what());
  }
  result.initial = report_design(spec, x0, q0);
  const double objective_scale =
      std::abs(result.initial.objective) > 0.0 ? std::abs(result.initial.objective) : 1.0;

  ScaledProgram program(evaluator, objective_scale);
  NlpProblem nlp;
  nlp.lower.assign(spec.variables.size(), 0.0);
  nlp.upper.assign(spec.variables.size(), 1.0);
  nlp.start = program.to_scaled(x0);
  program.seed(nlp.start, q0, "initial");
  for (const auto& k : spec.constraints) {
    const double scale = constraint_scale(k);
    nlp.g_lower.push_back(std::isfinite(k.lower) ? k.lower / scale : -kNoBound);
    nlp.g_upper.push_back(std::isfinite(k.upper) ? k.upper / scale : kNoBound);
  }
  nlp.values = [&](const std::vector<double>& u, double& f, std::vector<double>& g) {
    return program.values(u, f, g);
  };
  nlp.derivatives = [&](const std::vector<double>& u, std::vector<double>& grad,
                        std::vector<double>& jacobian) {
    return program.derivatives(u, grad, jacobian);
  };
  IpoptSettings settings;
  settings.max_iterations = spec.max_iterations;
  settings.tolerance = spec.tolerance;
  settings.print_level = options.print_level;

  // Ipopt on the morphed mesh; the optimum is then checked on a fresh mesh of its own geometry
  // (what `rheomag solve` of the written case uses). If that check violates a constraint (the
  // morphed and the fresh mesh differ by the discretisation error), Ipopt restarts from the
  // optimum with the fresh mesh as the new morph reference.
  std::vector<double> x_opt;
  Quantities q_opt;
  for (int pass = 0; pass <= kRestarts; ++pass) {
    const NlpResult solved = solve_nlp(nlp, settings);
    result.status = solved.status;
    result.converged = solved.converged;
    result.iterations += solved.iterations;
    x_opt = program.to_design(solved.x);
    for (std::size_t i = 0; i < x_opt.size(); ++i)
      x_opt[i] = std::clamp(x_opt[i], spec.variables[i].lower, spec.variables[i].upper);
    evaluator.remesh_next();
    program.forget();
    q_opt = evaluator.evaluate(x_opt);
    result.optimal = report_design(spec, x_opt, q_opt);
    if (result.optimal.feasible || solved.infeasible) break;
    nlp.start = program.to_scaled(x_opt);
  }
  // Counts (turns) to whole numbers: nearest, all down, all up; the best feasible candidate
  // (checked on a fresh mesh) wins, else the nearest.
  std::vector<std::size_t> counts;
  for (std::size_t i = 0; i < x_opt.size(); ++i)
    if (is_count_key(c.table, spec.variables[i].key)) counts.push_back(i);
  if (!counts.empty()) {
    std::optional<DesignReport> chosen;
    for (int mode = 0; mode < 3; ++mode) {
      std::vector<double> x = x_opt;
      for (std::size_t i : counts) {
        const double v = mode == 0   ? std::round(x[i])
                         : mode == 1 ? std::floor(x[i])
                                     : std::ceil(x[i]);
        x[i] =
            std::clamp(v, std::ceil(spec.variables[i].lower), std::floor(spec.variables[i].upper));
      }
      evaluator.remesh_next();
      DesignReport candidate = report_design(spec, x, evaluator.evaluate(x));
      const bool better = !chosen || (candidate.feasible && !chosen->feasible) ||
                          (candidate.feasible == chosen->feasible &&
                           (spec.maximise ? candidate.objective > chosen->objective
                                          : candidate.objective < chosen->objective));
      if (better) chosen = std::move(candidate);
    }
    x_opt = chosen->x;
    result.optimal = *chosen;
    evaluator.remesh_next();
    evaluator.evaluate(x_opt);  // the chosen design's field for the .vtu
  }
  if (!result.optimal.feasible) {
    for (const auto& s : result.optimal.constraints)
      if (!s.satisfied || s.active)
        result.conflicts.push_back(bound_text(s.constraint) + " (" + s.constraint.where +
                                   "): value " + number_text(s.value) +
                                   (s.satisfied ? ", at its bound" : ", VIOLATED"));
    for (const auto& key : result.optimal.variables_at_bounds)
      result.conflicts.push_back("design variable " + key + " at its bound");
  }

  std::filesystem::create_directories(options.out_dir);
  std::vector<std::string> keys;
  for (const auto& v : spec.variables) keys.push_back(v.key);
  const std::string stem = c.name.empty() ? c.source.stem().string() : c.name;
  result.case_file = options.out_dir / (stem + "_optimal.toml");
  result.history_file = options.out_dir / (stem + "_history.csv");
  result.vtu_file = options.out_dir / (stem + "_optimal.vtu");
  std::string header = "# Optimal design of " + c.source.filename().string() +
                       " by rheomag optimise (" + result.status + ")\n";
  write_file_atomically(result.case_file,
                        header + toml_text(with_values(c.table, keys, x_opt)) + "\n");
  write_file_atomically(result.history_file, history_csv(spec, program.history()));
  const auto& field = evaluator.last_field();
  magnetostatics::write_results_vtu(result.vtu_file.string(), *field.solver, field.solution,
                                    field.results);
  result.fe_solves = evaluator.fe_solves();
  result.meshes = evaluator.meshes();
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

std::string format_summary(const OptimiseResult& r) {
  std::ostringstream out;
  out << "Ipopt: " << r.status << " after " << r.iterations << " iterations, " << r.fe_solves
      << " FE solves, " << r.meshes << " mesh(es), " << number_text(r.seconds) << " s\n\n";
  char line[200];
  std::snprintf(line, sizeof line, "%-28s %14s %14s\n", "design variable", "initial", "optimal");
  out << line;
  for (std::size_t i = 0; i < r.spec.variables.size(); ++i) {
    std::snprintf(line, sizeof line, "%-28s %14.6g %14.6g\n", r.spec.variables[i].key.c_str(),
                  r.initial.x[i], r.optimal.x[i]);
    out << line;
  }
  std::snprintf(line, sizeof line, "\n%-28s %14s %14s\n", "quantity", "initial", "optimal");
  out << line;
  for (const auto& [name, unit] : quantity_units()) {
    auto a = r.initial.quantities.find(name), b = r.optimal.quantities.find(name);
    if (a == r.initial.quantities.end() || b == r.optimal.quantities.end()) continue;
    const std::string label = name + " [" + unit + "]";
    std::snprintf(line, sizeof line, "%-28s %14.6g %14.6g\n", label.c_str(), a->second, b->second);
    out << line;
  }
  if (!r.spec.constraints.empty()) out << "\nconstraints (optimal design):\n";
  for (const auto& s : r.optimal.constraints)
    out << "  " << bound_text(s.constraint) << ": " << number_text(s.value)
        << (s.satisfied ? (s.active ? "  active" : "  inactive") : "  VIOLATED") << "\n";
  for (const auto& key : r.optimal.variables_at_bounds) out << "  bound active: " << key << "\n";
  out << "\n"
      << (r.optimal.feasible ? "feasible" : "INFEASIBLE") << " optimum; objective "
      << (r.spec.maximise ? "max " : "min ") << r.spec.objective << ": "
      << number_text(r.initial.objective) << " -> " << number_text(r.optimal.objective) << "\n";
  if (!r.conflicts.empty()) {
    out << "No feasible design found within the bounds; the conflicting constraints at the "
           "least-violating design:\n";
    for (const auto& c : r.conflicts) out << "  " << c << "\n";
  }
  out << "\nwritten: " << r.case_file.string() << ", " << r.history_file.string() << ", "
      << r.vtu_file.string() << "\n";
  return out.str();
}

}  // namespace rheomag::optimise
