#include "optimise/ipopt.hpp"

#include <coin/IpIpoptApplication.hpp>
#include <coin/IpSolveStatistics.hpp>
#include <coin/IpTNLP.hpp>

#include "core/error.hpp"

namespace rheomag::optimise {

namespace {

using Ipopt::Index;
using Ipopt::Number;

class DenseTnlp : public Ipopt::TNLP {
 public:
  DenseTnlp(const NlpProblem& problem, const std::function<void(int)>& on_iteration)
      : p_(problem), on_iteration_(on_iteration) {}

  bool intermediate_callback(Ipopt::AlgorithmMode, Index iter, Number, Number, Number, Number,
                             Number, Number, Number, Number, Index, const Ipopt::IpoptData*,
                             Ipopt::IpoptCalculatedQuantities*) override {
    if (on_iteration_) on_iteration_(static_cast<int>(iter));
    return true;
  }

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = static_cast<Index>(p_.start.size());
    m = static_cast<Index>(p_.g_lower.size());
    nnz_jac_g = n * m;
    nnz_h_lag = 0;
    index_style = C_STYLE;
    return true;
  }
  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    for (Index i = 0; i < n; ++i) {
      x_l[i] = p_.lower[i];
      x_u[i] = p_.upper[i];
    }
    for (Index j = 0; j < m; ++j) {
      g_l[j] = p_.g_lower[j];
      g_u[j] = p_.g_upper[j];
    }
    return true;
  }
  bool get_starting_point(Index n, bool, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    for (Index i = 0; i < n; ++i) x[i] = p_.start[i];
    return true;
  }
  bool eval_f(Index n, const Number* x, bool, Number& f) override {
    if (!values_at(n, x)) return false;
    f = f_;
    return true;
  }
  bool eval_g(Index n, const Number* x, bool, Index m, Number* g) override {
    if (!values_at(n, x)) return false;
    for (Index j = 0; j < m; ++j) g[j] = g_[j];
    return true;
  }
  bool eval_grad_f(Index n, const Number* x, bool, Number* grad) override {
    if (!derivatives_at(n, x)) return false;
    for (Index i = 0; i < n; ++i) grad[i] = grad_[i];
    return true;
  }
  bool eval_jac_g(Index n, const Number* x, bool, Index m, Index, Index* rows, Index* cols,
                  Number* values) override {
    if (values == nullptr) {
      for (Index j = 0, k = 0; j < m; ++j)
        for (Index i = 0; i < n; ++i, ++k) {
          rows[k] = j;
          cols[k] = i;
        }
      return true;
    }
    if (!derivatives_at(n, x)) return false;
    for (Index k = 0; k < n * m; ++k) values[k] = jacobian_[k];
    return true;
  }
  void finalize_solution(Ipopt::SolverReturn, Index n, const Number* x, const Number* z_lower,
                         const Number* z_upper, Index m, const Number* g, const Number*, Number f,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    result.x.assign(x, x + n);
    result.bound_multipliers.resize(n);
    for (Index i = 0; i < n; ++i) result.bound_multipliers[i] = z_lower[i] - z_upper[i];
    result.g.assign(g, g + m);
    result.f = f;
  }

  NlpResult result;

 private:
  bool same(const std::vector<double>& cached, Index n, const Number* x) const {
    if (cached.size() != static_cast<std::size_t>(n)) return false;
    for (Index i = 0; i < n; ++i)
      if (cached[i] != x[i]) return false;
    return true;
  }
  bool values_at(Index n, const Number* x) {
    if (same(values_x_, n, x)) return values_ok_;
    values_x_.assign(x, x + n);
    g_.assign(p_.g_lower.size(), 0.0);
    values_ok_ = p_.values(values_x_, f_, g_);
    return values_ok_;
  }
  bool derivatives_at(Index n, const Number* x) {
    if (same(derivatives_x_, n, x)) return derivatives_ok_;
    derivatives_x_.assign(x, x + n);
    grad_.assign(n, 0.0);
    jacobian_.assign(n * p_.g_lower.size(), 0.0);
    derivatives_ok_ = p_.derivatives(derivatives_x_, grad_, jacobian_);
    return derivatives_ok_;
  }

  const NlpProblem& p_;
  const std::function<void(int)>& on_iteration_;
  std::vector<double> values_x_, derivatives_x_, g_, grad_, jacobian_;
  double f_ = 0.0;
  bool values_ok_ = false, derivatives_ok_ = false;
};

}  // namespace

NlpResult solve_nlp(const NlpProblem& problem, const IpoptSettings& settings) {
  Ipopt::SmartPtr<DenseTnlp> nlp = new DenseTnlp(problem, settings.on_iteration);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetStringValue("hessian_approximation", "limited-memory");
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetIntegerValue("print_level", settings.print_level);
  app->Options()->SetIntegerValue("max_iter", settings.max_iterations);
  app->Options()->SetNumericValue("tol", settings.tolerance);
  app->Options()->SetNumericValue("acceptable_tol", 10.0 * settings.tolerance);
  app->Options()->SetIntegerValue("acceptable_iter", 5);
  if (app->Initialize() != Ipopt::Solve_Succeeded)
    throw ConvergenceError("Ipopt: could not initialise");
  const Ipopt::ApplicationReturnStatus status = app->OptimizeTNLP(nlp);
  NlpResult result = nlp->result;
  result.converged =
      status == Ipopt::Solve_Succeeded || status == Ipopt::Solved_To_Acceptable_Level;
  result.infeasible = status == Ipopt::Infeasible_Problem_Detected;
  if (Ipopt::IsValid(app->Statistics())) result.iterations = app->Statistics()->IterationCount();
  switch (status) {
    case Ipopt::Solve_Succeeded:
      result.status = "solved";
      break;
    case Ipopt::Solved_To_Acceptable_Level:
      result.status = "solved to acceptable level";
      break;
    case Ipopt::Infeasible_Problem_Detected:
      result.status = "infeasible problem detected";
      break;
    case Ipopt::Maximum_Iterations_Exceeded:
      result.status = "maximum iterations exceeded";
      break;
    case Ipopt::Restoration_Failed:
      result.status = "restoration phase failed";
      break;
    case Ipopt::Search_Direction_Becomes_Too_Small:
      result.status = "search direction too small";
      break;
    case Ipopt::Error_In_Step_Computation:
      result.status = "error in step computation";
      break;
    case Ipopt::Invalid_Number_Detected:
      result.status = "invalid number detected";
      break;
    default:
      result.status = "Ipopt status " + std::to_string(static_cast<int>(status));
  }
  if (result.x.empty()) {
    throw ConvergenceError("Ipopt stopped before any iterate (" + result.status +
                           "): the starting design could not be evaluated");
  }
  return result;
}

}  // namespace rheomag::optimise
