#pragma once
// A dense, smooth nonlinear program solved by Ipopt 3.11 (interior point, limited-memory BFGS
// Hessian): min f(x) subject to lower <= x <= upper, g_lower <= g(x) <= g_upper.

#include <functional>
#include <string>
#include <vector>

namespace rheomag::optimise {

/// The program: bounds, start, and callbacks for values and first derivatives.
struct NlpProblem {
  std::vector<double> lower, upper, start;  ///< n variables
  std::vector<double> g_lower, g_upper;     ///< m constraints (use +-1e19 for none)
  /// f and g (size m) at x; false if x cannot be evaluated (Ipopt then backtracks).
  std::function<bool(const std::vector<double>& x, double& f, std::vector<double>& g)> values;
  /// grad f (size n) and the dense Jacobian of g (row-major, m x n) at x; false on failure.
  std::function<bool(const std::vector<double>& x, std::vector<double>& grad,
                     std::vector<double>& jacobian)>
      derivatives;
};

/// Ipopt options used.
struct IpoptSettings {
  int max_iterations = 100;
  double tolerance = 1e-8;  ///< Ipopt "tol"
  int print_level = 0;      ///< Ipopt output to stdout (0 = silent)
  /// Called after each Ipopt iteration with its number (0: the starting point); may be empty.
  std::function<void(int iteration)> on_iteration;
};

/// What Ipopt returned.
struct NlpResult {
  std::vector<double> x, g;
  double f = 0.0;
  bool converged = false;   ///< Solve_Succeeded or Solved_To_Acceptable_Level
  bool infeasible = false;  ///< Infeasible_Problem_Detected
  std::string status;       ///< Ipopt's return status as text
  int iterations = 0;
  /// Bound multipliers at the solution per variable, z_lower - z_upper (> 0: f would fall
  /// below the lower bound, < 0: above the upper; about 0 off the bounds).
  std::vector<double> bound_multipliers;
};

/// Solves the program with Ipopt (hessian_approximation limited-memory). Throws
/// ConvergenceError if Ipopt cannot start (e.g. the start cannot be evaluated).
NlpResult solve_nlp(const NlpProblem& problem, const IpoptSettings& settings = {});

}  // namespace rheomag::optimise
