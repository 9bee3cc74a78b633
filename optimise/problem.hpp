#pragma once
// The scaled nonlinear program of an [optimise] spec around any design evaluator (the FE one,
// or an analytic model in tests): u in [0, 1]^n, f = -+objective / scale, g_j = quantity_j /
// scale_j, central- or forward-difference derivatives, every evaluation cached and recorded.

#include <functional>
#include <map>
#include <string>
#include <vector>

#include "optimise/ipopt.hpp"
#include "optimise/spec.hpp"

namespace rheomag::optimise {

/// Quantities of a design (file units); throws for a design that cannot be evaluated.
/// `neighbour`: x is a point of a finite-difference stencil, whose evaluations may reuse the
/// work of the last design evaluated as not a neighbour (all points of one stencil alike).
using EvaluateDesign =
    std::function<design::Quantities(const std::vector<double>& x, bool neighbour)>;

/// One evaluated design, for the history CSV.
struct HistoryRow {
  std::string purpose;  ///< initial, iterate, gradient, ...
  std::vector<double> x;
  design::Quantities q;
  bool ok = true;
  std::string error;
};

/// Scale of a constraint: its largest finite bound in magnitude (1 if both are 0).
double constraint_scale(const Constraint& c);

/// Value of a quantity; InputError if the design does not provide it (or it is not finite).
double quantity_value(const design::Quantities& q, design::Quantity quantity);

/// The program Ipopt sees for one spec (see file comment).
class ScaledProgram {
 public:
  /// `spec` must outlive the program; evaluations are appended to `history`.
  ScaledProgram(const OptimiseSpec& spec, EvaluateDesign evaluate, double objective_scale,
                std::vector<HistoryRow>& history);
  /// Design values (file units) of scaled u, and back.
  std::vector<double> to_design(const std::vector<double>& u) const;
  std::vector<double> to_scaled(const std::vector<double>& x) const;
  /// Records an evaluation done outside the program so Ipopt does not repeat it.
  void seed(const std::vector<double>& x, const design::Quantities& q, const std::string& purpose);
  /// Drops the cached evaluations (after the reference mesh changed).
  void forget() {
    cache_.clear();
    last_centre_.clear();
  }
  /// Runs Ipopt from design `start` (file units).
  NlpResult solve(const std::vector<double>& start, const IpoptSettings& settings);
  /// Ipopt's callbacks at scaled u: f and g, false if the design cannot be evaluated.
  bool values(const std::vector<double>& u, double& f_value, std::vector<double>& g_value);
  /// Ipopt's callbacks at scaled u: the gradient of f and the Jacobian of g (row-major, one row
  /// per constraint) by the spec's differences; false if a design cannot be evaluated.
  bool derivatives(const std::vector<double>& u, std::vector<double>& grad,
                   std::vector<double>& jacobian);

 private:
  const design::Quantities* at(const std::vector<double>& u, const std::string& purpose);
  double f(const design::Quantities& q) const;
  void g(const design::Quantities& q, std::vector<double>& out) const;
  /// u evaluated again as not a neighbour (its cached evaluation replaced), so that the
  /// forward differences' neighbours reuse its work.
  const design::Quantities* evaluate_centre(const std::vector<double>& u);

  const OptimiseSpec& spec_;
  EvaluateDesign evaluate_;
  double objective_scale_;
  std::vector<HistoryRow>& history_;
  std::map<std::vector<double>, HistoryRow> cache_;
  std::vector<double> last_centre_;  ///< u of the last design evaluated as not a neighbour
};

/// The history CSV: evaluation, purpose, the design, every quantity, the error.
std::string history_csv(const OptimiseSpec& spec, const std::vector<HistoryRow>& rows);

/// "%.6g" of a number.
std::string number_text(double v);

}  // namespace rheomag::optimise
