#include "transient/quasi_static.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "transient/gap_flux.hpp"

// Boost 1.74's pchip.hpp calls isnan unqualified in a template; make std::isnan visible there.
using std::isnan;
#include <boost/math/interpolators/cubic_hermite.hpp>
#include <boost/math/interpolators/pchip.hpp>
#include <boost/math/quadrature/gauss.hpp>
#include <boost/math/tools/roots.hpp>

namespace rheomag::transient {
namespace {

using Hermite = boost::math::interpolators::cubic_hermite<std::vector<double>>;
using Pchip = boost::math::interpolators::pchip<std::vector<double>>;

/// One column of the table.
std::vector<double> column(const QuasiStaticTable& table,
                           const std::function<double(const QuasiStaticPoint&)>& of) {
  std::vector<double> out;
  for (const QuasiStaticPoint& p : table.points) out.push_back(of(p));
  return out;
}

/// The first current from `from` towards `to` at which `q` reaches `target` coming from q(from)
/// (the table's currents `grid` as breakpoints); nothing when it does not.
std::optional<double> first_crossing(const std::function<double(double)>& q, double target,
                                     double from, double to, const std::vector<double>& grid) {
  const double sense = q(to) >= q(from) ? 1.0 : -1.0;
  auto reached = [&](double i) { return sense * (q(i) - target) >= 0.0; };
  if (reached(from)) return from;
  std::vector<double> stops;
  for (double c : grid)
    if ((c - from) * (to - c) > 0.0) stops.push_back(c);
  if (to < from) std::reverse(stops.begin(), stops.end());
  stops.insert(stops.begin(), from);
  stops.push_back(to);
  for (std::size_t k = 1; k < stops.size(); ++k) {
    if (!reached(stops[k])) continue;
    boost::math::tools::eps_tolerance<double> tolerance(50);
    std::uintmax_t iterations = 200;
    const double lo = std::min(stops[k - 1], stops[k]), hi = std::max(stops[k - 1], stops[k]);
    const auto [a, b] = boost::math::tools::toms748_solve([&](double i) { return q(i) - target; },
                                                          lo, hi, tolerance, iterations);
    return 0.5 * (a + b);
  }
  return std::nullopt;
}

/// The table's interpolants as quasi_static_step uses them, to check a new current against.
class TableInterpolants {
 public:
  /// Interpolants of `table` (at least 4 currents).
  explicit TableInterpolants(const QuasiStaticTable& table)
      : lambda_(column(table, [](auto& p) { return p.current; }),
                column(table, [](auto& p) { return p.flux_linkage; }),
                column(table, [](auto& p) { return p.inductance; })),
        inductance_(column(table, [](auto& p) { return p.current; }),
                    column(table, [](auto& p) { return p.inductance; })),
        eddy_load_(column(table, [](auto& p) { return p.current; }),
                   column(table, [](auto& p) { return p.eddy_load; })) {
    for (const QuasiStaticPoint& p : table.points)
      lambda_scale_ = std::max(lambda_scale_, std::abs(p.flux_linkage));
    for (std::size_t g = 0; g < table.gap_regions.size(); ++g) {
      gap_b_.emplace_back(column(table, [](auto& p) { return p.current; }),
                          column(table, [&](auto& p) { return p.gap_b.at(g); }),
                          column(table, [&](auto& p) { return p.gap_b_slope.at(g); }));
      double scale = 0.0;
      for (const QuasiStaticPoint& p : table.points) scale = std::max(scale, std::abs(p.gap_b[g]));
      gap_b_scale_.push_back(scale);
    }
  }

  /// Largest relative error of the interpolants at `solved`'s current: L_d and D against their
  /// own values, lambda and each gap's mean |B| against their largest in the table.
  double discrepancy(const QuasiStaticPoint& solved) const {
    const double i = solved.current;
    auto relative = [](double predicted, double value, double scale) {
      return scale > 0.0 ? std::abs(predicted - value) / scale : 0.0;
    };
    double worst =
        std::max({relative(inductance_(i), solved.inductance, std::abs(solved.inductance)),
                  relative(eddy_load_(i), solved.eddy_load, std::abs(solved.eddy_load)),
                  relative(lambda_(i), solved.flux_linkage, lambda_scale_)});
    for (std::size_t g = 0; g < gap_b_.size(); ++g)
      worst = std::max(worst, relative(gap_b_[g](i), solved.gap_b.at(g), gap_b_scale_[g]));
    return worst;
  }

 private:
  Hermite lambda_;
  Pchip inductance_, eddy_load_;
  std::vector<Hermite> gap_b_;
  double lambda_scale_ = 0.0;
  std::vector<double> gap_b_scale_;
};

// Whether contracting steps (step_j = rho step_j-1) have settled: the error the last one leaves,
// rho / (1 - rho) |step|, is within kDifferenceTolerance of `change`, the neighbour's difference
// from its centre that a finite difference divides, and of 1e-3 of `size`, the solution's norm
// (so a distant design is solved to 1e-8 of its solution, as Newton would). A forward difference
// of step 1e-3 is itself about 1e-3 off, so an error of 1e-5 of the change does not show in it.
constexpr double kDifferenceTolerance = 1e-5;
bool settled(double step, double previous_step, double change, double size) {
  if (!(previous_step > 0.0)) return false;
  const double rho = step / previous_step;
  return rho < 0.01 &&
         rho / (1.0 - rho) * step <= kDifferenceTolerance * std::min(change, 1e-3 * size);
}

}  // namespace

QuasiStaticTable quasi_static_table(TransientSolver& solver, double low, double high, int points) {
  return quasi_static_table(solver, low, high, points, QuasiStaticReuse{});
}

QuasiStaticTable quasi_static_table(TransientSolver& solver, double low, double high, int points,
                                    const QuasiStaticReuse& reuse) {
  magnetostatics::MagnetostaticSolver& statics = solver.statics();
  const std::string where = statics.problem().geometry.source;
  if (!(std::isfinite(low) && std::isfinite(high) && low < high) || points < 4)
    throw InputError(format_text(
        "%s: quasi-static response: expected at least 4 currents over a finite range low < high, "
        "got %d over [%.6g, %.6g] A",
        where.c_str(), points, low, high));
  const QuasiStaticStart* earlier = reuse.start;
  if (earlier &&
      (earlier->fields.empty() || earlier->fields.size() != earlier->fractions.size() ||
       earlier->currents.size() != earlier->fields.size() ||
       earlier->slopes.size() != earlier->fields.size() ||
       static_cast<std::size_t>(earlier->fields.front().size()) != statics.mesh().nodes.size()))
    earlier = nullptr;  // another mesh: no warm starts
  QuasiStaticTable table;
  table.gap_regions = gap_regions(statics);
  std::vector<double> currents;
  if (earlier && reuse.fixed_grid)
    for (double f : earlier->fractions) currents.push_back(low + (high - low) * f);
  else
    for (int k = 0; k < points; ++k) currents.push_back(low + (high - low) * k / (points - 1));
  const magnetostatics::DofMap& dofs = statics.dofs();
  const auto mass = solver.damping().selfadjointView<Eigen::Lower>();
  std::vector<double> held;
  for (const cases::Circuit& circuit : statics.problem().circuits) held.push_back(circuit.current);
  // Nodal A of each point and its dA/di_m, for tangent predictions of the next solves' starts.
  std::vector<Eigen::VectorXd> fields, slopes;
  // Of two starts for the solve at `held`, the one with the smaller residual; on a fixed grid
  // (a finite-difference neighbour of the earlier design) the earlier design's, without the
  // two residuals' cost.
  auto closer = [&](Eigen::VectorXd a, const std::optional<Eigen::VectorXd>& b) {
    if (b &&
        (reuse.fixed_grid || statics.residual(*b, held).norm() < statics.residual(a, held).norm()))
      return *b;
    return a;
  };
  // The earlier design's state nearest to `current`, moved to it along its slope.
  auto earlier_at = [&](double current) -> Eigen::VectorXd {
    std::size_t k = 0;
    for (std::size_t j = 1; j < earlier->currents.size(); ++j)
      if (std::abs(earlier->currents[j] - current) < std::abs(earlier->currents[k] - current))
        k = j;
    return earlier->fields[k] + (current - earlier->currents[k]) * earlier->slopes[k];
  };
  // The earlier design's state at `current` plus the difference between the designs at the
  // table's solved point `solved` (smooth in the current, so carried over).
  auto from_earlier = [&](double current,
                          std::optional<std::size_t> solved) -> std::optional<Eigen::VectorXd> {
    if (!earlier) return std::nullopt;
    Eigen::VectorXd a = earlier_at(current);
    if (solved) a += fields[*solved] - earlier_at(table.points[*solved].current);
    return a;
  };
  // Factorisations of the tangent at each point (reuse.keep_factors).
  std::vector<std::shared_ptr<const magnetostatics::FrozenFactor>> factors;
  std::vector<Eigen::VectorXd> residuals;
  const bool keep_factors = reuse.keep && reuse.keep_factor_bytes > 0;
  std::size_t factor_bytes = 0;  // held by `factors`
  // Kept factorisations are of the tangent at each solution: its dA/di_m is solved with that
  // factorisation rather than by CG before it is made (restored on every exit).
  struct FactoriseIncremental {
    magnetostatics::MagnetostaticSolver& statics;
    FactoriseIncremental(magnetostatics::MagnetostaticSolver& s, bool on) : statics(s) {
      statics.factorise_incremental_tangent(on);
    }
    ~FactoriseIncremental() { statics.factorise_incremental_tangent(false); }
  } factorise_incremental(statics, keep_factors);
  // Inserts the point at `current` with nodal A `a`, dA/di_m `slope` (free dofs), lambda and
  // L_d at `at`.
  auto insert = [&](double current, const Eigen::VectorXd& a, const Eigen::VectorXd& slope,
                    double flux_linkage, double inductance, std::size_t at) {
    Eigen::VectorXd slope_nodes = Eigen::VectorXd::Zero(a.size());
    for (int d = 0; d < dofs.free_count(); ++d) slope_nodes[dofs.node_of_dof[d]] = slope[d];
    const MeanBSlope gaps =
        region_mean_b_slope(statics, table.gap_regions, a, slope_nodes, slope_nodes);
    const auto place = static_cast<std::ptrdiff_t>(at);
    table.points.insert(
        table.points.begin() + place,
        {current, flux_linkage, inductance, slope.dot(mass * slope), gaps.b, gaps.slope});
    fields.insert(fields.begin() + place, a);
    slopes.insert(slopes.begin() + place, std::move(slope_nodes));
  };
  // The static state at `current` by Newton from nodal A `guess`, inserted at `at`.
  auto newton_at = [&](double current, const Eigen::VectorXd& guess, std::size_t at) {
    held[0] = current;
    const magnetostatics::Solution s = statics.solve_incremental(held, &guess);
    insert(current, s.a, s.incremental_field.at(0), s.flux_linkage.at(0),
           s.incremental_inductance.at(0), at);
    if (keep_factors) {
      std::shared_ptr<const magnetostatics::FrozenFactor> factor;
      if (factor_bytes < reuse.keep_factor_bytes) factor = statics.freeze_tangent_factor();
      if (factor && (factor_bytes += factor->bytes()) > reuse.keep_factor_bytes) factor.reset();
      factors.insert(factors.begin() + static_cast<std::ptrdiff_t>(at), std::move(factor));
      residuals.insert(residuals.begin() + static_cast<std::ptrdiff_t>(at), s.residual);
    }
    table.newton_iterations += s.newton.iterations;
  };
  // The static state at `current` from nodal A `start`, inserted at `at`; `solved`: a neighbour
  // already in the table.
  auto solve_at = [&](double current, const Eigen::VectorXd& start, std::size_t at,
                      std::optional<std::size_t> solved) {
    held[0] = current;
    newton_at(current, closer(start, from_earlier(current, solved)), at);
  };
  // Linearised neighbours: the earlier design's states and factorisations, on its grid.
  const bool linearise = earlier && reuse.fixed_grid && reuse.linearise && !dofs.constrained() &&
                         earlier->factors.size() == earlier->fields.size() &&
                         earlier->residuals.size() == earlier->fields.size();
  // A table that keeps its own factorisations releases the earlier ones first (`keep` may be
  // `start`): the memory then holds one table's.
  if (reuse.keep && !linearise) reuse.keep->factors.clear();
  auto linearisable = [&](std::size_t k) {
    return linearise && earlier->factors[k] && earlier->factors[k]->size() == dofs.free_count() &&
           earlier->residuals[k].size() == dofs.free_count();
  };
  // The state at `current` (the earlier design's state k) from the earlier state A0 by chord
  // steps with its tangent's factorisation K0, A_j+1 = A_j - K0^-1 (R(A_j) - R0), R0 the residual
  // Newton left at A0 (so this state keeps A0's error and the designs' difference is smooth),
  // until |R(A_j) - R0| is within Newton's tolerance (j >= 1; measured: 2 for a change of turns
  // on the same currents, 3 for a morphed mesh, whose residual at A0 is larger than the load;
  // j = 0 for a same_fraction state) or the steps have
  // settled (`settled`: then 2 where the residual needed 3); then dA/di_m from A0's
  // by steps s += K0^-1 (F - K(A_j) s). Both errors are second order in the designs' difference
  // (a tangent at A1 moved L_d by 10 % of its change in a saturation knee). Newton from A_4 when
  // the steps did not converge.
  constexpr int kChordSteps = 4;
  const magnetostatics::NewtonOptions& newton = statics.options().newton;
  // Whether the earlier states at the same fraction of the range have so far been this design's
  // own (dropped at the first miss): they are, to rounding, when the designs differ only in the
  // first circuit's turns (its source F scaled by s) and the range in V / R with R in proportion
  // to the turns, since state k then carries the same ampere-turns, I'_k = I_k / s, and
  // R'(A_k, I'_k) = K(A_k) - s F I_k / s = R(A_k, I_k). Such a state needs no chord step.
  bool same_fraction = low == 0.0;
  auto linearised_at = [&](double current, std::size_t k) {
    held[0] = current;
    const magnetostatics::FrozenFactor& factor = *earlier->factors[k];
    const Eigen::VectorXd& left = earlier->residuals[k];
    // Newton's scale: |R(A = 0)| = |F i + fixed sources| without magnets' assembled part.
    Eigen::VectorXd load = statics.fixed_source();
    for (std::size_t c = 0; c < held.size(); ++c) load += held[c] * statics.circuit_source(c);
    const double tolerance = newton.relative_tolerance * statics.nodes_to_free(load).norm();
    magnetostatics::SparseMatrix tangent;
    const Eigen::VectorXd centre = statics.nodes_to_free(earlier->fields[k]);
    bool converged = false;
    // dA/di_m's start: the earlier state's, scaled by I_k / I'_k when that state is this one.
    double slope_scale = 1.0;
    if (same_fraction && k > 0 && current > 0.0) {
      converged = (statics.residual(earlier->fields[k], held, tangent) - left).norm() <= tolerance;
      same_fraction = converged;
      if (converged) slope_scale = earlier->currents[k] / current, ++table.same_ampere_turns;
    }
    Eigen::VectorXd x =
        converged || k == 0 ? centre : statics.nodes_to_free(*from_earlier(current, k - 1));
    double previous_step = 0.0;
    for (int step = 0; step <= kChordSteps && !converged; ++step) {
      const Eigen::VectorXd r = statics.residual(statics.free_to_nodes(x), held, tangent) - left;
      converged = r.norm() <= tolerance;
      if (converged) break;
      const Eigen::VectorXd dx = factor.solve(r);
      x -= dx;
      const double step_norm = dx.norm();
      if (settled(step_norm, previous_step, (x - centre).norm(), x.norm())) {
        // Settled within the difference's tolerance: the tangent at the final state, for dA/di_m.
        statics.residual(statics.free_to_nodes(x), held, tangent);
        converged = true;
      }
      previous_step = step_norm;
    }
    if (!converged) {
      newton_at(current, statics.free_to_nodes(x), k);
      return;
    }
    const Eigen::VectorXd a = statics.free_to_nodes(x);
    const Eigen::VectorXd f = statics.nodes_to_free(statics.circuit_source(0));
    const Eigen::VectorXd centre_slope = statics.nodes_to_free(earlier->slopes[k]);
    Eigen::VectorXd slope = slope_scale * centre_slope;
    const auto full = tangent.selfadjointView<Eigen::Lower>();
    double previous_slope_step = 0.0;
    for (int step = 0; step < 4; ++step) {
      const Eigen::VectorXd change = factor.solve(f - full * slope);
      slope += change;
      // Converged when the step is small against the slope or has settled against the slope's
      // change from the centre's (measured on the reference valve: rho 3e-5 to 3e-3, so two
      // steps where 1e-12 of the slope took four).
      const double step_norm = change.norm();
      if (step_norm <= 1e-12 * slope.norm() ||
          settled(step_norm, previous_slope_step, (slope - centre_slope).norm(), slope.norm()))
        break;
      previous_slope_step = step_norm;
    }
    insert(current, a, slope, statics.circuit_source(0).dot(a), f.dot(slope), k);
    if (keep_factors) {
      factors.insert(factors.begin() + static_cast<std::ptrdiff_t>(k), nullptr);
      residuals.insert(residuals.begin() + static_cast<std::ptrdiff_t>(k), Eigen::VectorXd());
    }
    ++table.linearised;
  };
  // Tangent predictor from the last state; zero for the first.
  const auto nodes = static_cast<Eigen::Index>(statics.mesh().nodes.size());
  for (std::size_t k = 0; k < currents.size(); ++k)
    if (linearisable(k))
      linearised_at(currents[k], k);
    else
      solve_at(
          currents[k],
          k == 0 ? Eigen::VectorXd(Eigen::VectorXd::Zero(nodes))
                 : Eigen::VectorXd(fields.back() + (currents[k] - currents[k - 1]) * slopes.back()),
          k, k == 0 ? std::nullopt : std::optional<std::size_t>(k - 1));
  // Halve every interval whose midpoint the table did not predict (a saturation knee): each
  // unsettled interval gets its midpoint solved, and both halves settle when the table before
  // the solve had predicted it to kQuasiStaticTableTolerance.
  const std::size_t most = 16 * static_cast<std::size_t>(points);
  const bool refine = !(earlier && reuse.fixed_grid);
  std::vector<bool> settled(table.points.size() - 1, !refine);
  while (table.points.size() < most &&
         std::find(settled.begin(), settled.end(), false) != settled.end()) {
    const TableInterpolants before(table);
    for (std::size_t k = 0; k < settled.size() && table.points.size() < most; ++k) {
      if (settled[k]) continue;
      const QuasiStaticPoint &p = table.points[k], &q = table.points[k + 1];
      const double h = q.current - p.current;
      if (h < 1e-6 * (high - low)) {
        settled[k] = true;
        continue;
      }
      // Cubic Hermite midpoint of the two states and their slopes.
      const Eigen::VectorXd start =
          0.5 * (fields[k] + fields[k + 1]) + (h / 8.0) * (slopes[k] - slopes[k + 1]);
      solve_at(0.5 * (p.current + q.current), start, k + 1, k);
      const bool predicted = before.discrepancy(table.points[k + 1]) <= kQuasiStaticTableTolerance;
      settled[k] = predicted;
      settled.insert(settled.begin() + static_cast<std::ptrdiff_t>(k + 1), predicted);
      ++k;  // the new interval's right half is looked at in the next pass
    }
  }
  if (reuse.keep) {
    reuse.keep->fractions.clear();
    reuse.keep->currents.clear();
    for (const QuasiStaticPoint& p : table.points) {
      reuse.keep->fractions.push_back((p.current - low) / (high - low));
      reuse.keep->currents.push_back(p.current);
    }
    reuse.keep->fields = std::move(fields);
    reuse.keep->slopes = std::move(slopes);
    reuse.keep->factors = std::move(factors);
    reuse.keep->residuals = std::move(residuals);
  }
  return table;
}

QuasiStaticStep quasi_static_step(const QuasiStaticTable& table, double from_current,
                                  double final_current, double resistance) {
  if (table.points.size() < 4)
    throw InputError("quasi-static response: the table has fewer than 4 currents");
  const double low = table.points.front().current, high = table.points.back().current;
  const double slack = 1e-12 * (high - low);
  if (!(resistance > 0.0) || !std::isfinite(final_current) || !std::isfinite(from_current) ||
      final_current == from_current || from_current < low - slack || from_current > high + slack ||
      final_current < low - slack || final_current > high + slack)
    throw InputError(format_text(
        "quasi-static response: the step from %.6g A to %.6g A (resistance %.6g Ohm) must change "
        "the current within the table's [%.6g, %.6g] A",
        from_current, final_current, resistance, low, high));
  for (const QuasiStaticPoint& p : table.points)
    if (!(p.inductance > 0.0) || !(p.eddy_load >= 0.0))
      throw InputError(format_text(
          "quasi-static response: the incremental inductance at %.6g A is %.6g H (expected > 0)",
          p.current, p.inductance));
  const std::vector<double> grid = column(table, [](auto& p) { return p.current; });
  auto clamp = [&](double i) { return std::min(std::max(i, low), high); };
  const double from = clamp(from_current), to = clamp(final_current);
  const Hermite lambda(column(table, [](auto& p) { return p.current; }),
                       column(table, [](auto& p) { return p.flux_linkage; }),
                       column(table, [](auto& p) { return p.inductance; }));
  const Pchip inductance(column(table, [](auto& p) { return p.current; }),
                         column(table, [](auto& p) { return p.inductance; }));
  const Pchip eddy_load(column(table, [](auto& p) { return p.current; }),
                        column(table, [](auto& p) { return p.eddy_load; }));

  // Time to reach magnetising current i. With u = -ln((to - i) / (to - from)) the voltage
  // drive's di_m/dt = R (to - i_m) / (L_d + R D / L_d) gives dt = (L_d / R + D / L_d) du, smooth
  // up to the steady state; a current drive (R infinite) keeps D di_m/dt = L_d (i - i_m).
  auto time_to = [&](double i) {
    auto rate = [&](double u) {
      const double c = clamp(to - (to - from) * std::exp(-u)), l = inductance(c);
      return l / resistance + eddy_load(c) / l;
    };
    std::vector<double> breaks{0.0};
    for (double c : grid)
      if ((c - from) * (i - c) > 0.0) breaks.push_back(-std::log((to - c) / (to - from)));
    breaks.push_back(-std::log((to - i) / (to - from)));
    std::sort(breaks.begin(), breaks.end());
    double t = 0.0;
    for (std::size_t k = 1; k < breaks.size(); ++k)
      t += boost::math::quadrature::gauss<double, 10>::integrate(rate, breaks[k - 1], breaks[k]);
    return t;
  };
  auto rise = [&](const std::function<double(double)>& q,
                  double fraction) -> std::optional<double> {
    const double start = q(from), end = q(to);
    if (start == end) return std::nullopt;
    const auto i = first_crossing(q, start + fraction * (end - start), from, to, grid);
    if (!i) return std::nullopt;
    return time_to(*i);
  };

  QuasiStaticStep out;
  const double e_fold = 1.0 - std::exp(-1.0);
  const std::function<double(double)> flux = [&](double i) { return lambda(i); };
  out.t63 = rise(flux, e_fold);
  out.t90 = rise(flux, 0.9);
  for (std::size_t g = 0; g < table.gap_regions.size(); ++g) {
    const Hermite b(column(table, [](auto& p) { return p.current; }),
                    column(table, [&](auto& p) { return p.gap_b.at(g); }),
                    column(table, [&](auto& p) { return p.gap_b_slope.at(g); }));
    const std::function<double(double)> gap = [&](double i) { return b(i); };
    out.gap_b_from.push_back(b(from));
    out.gap_b_final.push_back(b(to));
    out.gap_t63.push_back(rise(gap, e_fold));
    out.gap_t90.push_back(rise(gap, 0.9));
  }
  return out;
}

}  // namespace rheomag::transient
