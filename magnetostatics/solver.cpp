#include "magnetostatics/solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <sstream>

#include "core/error.hpp"
#include "magnetostatics/cholmod_status.hpp"
#include "magnetostatics/huge_pages.hpp"
#include "magnetostatics/local_correction.hpp"
#include "magnetostatics/preconditioned_cg.hpp"
#include "magnetostatics/serial_openmp.hpp"

namespace rheomag::magnetostatics {

/// The discrete magnetostatic equations for fixed currents, as seen by Newton.
class MagnetostaticSolver::System : public NonlinearSystem {
 public:
  System(MagnetostaticSolver& solver, Eigen::VectorXd source)
      : solver_(solver), source_(std::move(source)) {}

  double residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) override {
    if (x.size() == remembered_x_.size() && x == remembered_x_) {
      r = remembered_r_;  // Newton's first residual is often the one solve_with evaluated
      return r.norm();
    }
    if (with_tangent_) {
      solver_.assemble_residual_tangent(solver_.reduced_to_nodes(x), r);
    } else {
      solver_.assembler_->assemble(solver_.reduced_to_nodes(x), r, nullptr);
      ++solver_.assemblies_;
    }
    if (solver_.dofs_.constrained()) r = solver_.dofs_.reduce(r);
    r -= source_;
    remember(x, r);
    return r.norm();
  }
  /// R(0), the residual with no field, from the solver's cached assembly at A = 0.
  double residual_at_zero(Eigen::VectorXd& r) {
    r = solver_.zero_field_load();
    r -= source_;
    return r.norm();
  }
  /// Stored energy plus boundary terms minus the sources' work: R = grad E.
  double energy(const Eigen::VectorXd& x) override {
    return solver_.assembler_->energy(solver_.reduced_to_nodes(x)) - source_.dot(x);
  }
  int correct_locally(Eigen::VectorXd& x, Eigen::VectorXd& r, double& norm) override {
    // One Newton step solves a linear problem everywhere; the patches of local corrections
    // do not follow periodic pairs.
    if (solver_.linear_ || solver_.dofs_.constrained()) return 0;
    Eigen::VectorXd a = solver_.free_to_nodes(x);
    const int steps = magnetostatics::correct_locally(*solver_.assembler_, solver_.dofs_, source_,
                                                      solver_.options_.newton, a, r, norm);
    for (int d = 0; steps > 0 && d < solver_.dofs_.free_count(); ++d) {
      x[d] = a[solver_.dofs_.node_of_dof[d]];
    }
    return steps;
  }
  /// From now on each residual also assembles the tangent at its x, which the Jacobian at the
  /// same x then takes as it is (Newton's accepted iterate and the solution of an incremental
  /// solve: one assembly less each; wasted where local corrections move the iterate).
  void assemble_tangents() { with_tangent_ = !solver_.linear_; }
  /// Keeps R(x) for a later residual call at the same x (one assembly less); the last residual
  /// evaluated is kept too.
  void remember(const Eigen::VectorXd& x, const Eigen::VectorXd& r) {
    remembered_x_ = x;
    remembered_r_ = r;
  }
  void factorize_jacobian(const Eigen::VectorXd& x) override {
    solver_.prepare_jacobian(solver_.reduced_to_nodes(x));
  }
  Eigen::VectorXd solve_jacobian(const Eigen::VectorXd& rhs, double tolerance) override {
    return solver_.solve_jacobian(rhs, tolerance);
  }

 private:
  MagnetostaticSolver& solver_;
  Eigen::VectorXd source_;  // free-dof source at the solve's currents
  Eigen::VectorXd remembered_x_, remembered_r_;
  bool with_tangent_ = false;
};

MagnetostaticSolver::MagnetostaticSolver(cases::Problem problem, mesh::Mesh mesh,
                                         SolveOptions options)
    : problem_(std::move(problem)), mesh_(std::move(mesh)), options_(options) {
  if (mesh_.region.size() != mesh_.triangles.size()) {
    throw InputError("mesh has " + std::to_string(mesh_.triangles.size()) + " triangles but " +
                     std::to_string(mesh_.region.size()) + " region ids");
  }
  if (problem_.symmetry == cases::Symmetry::planar &&
      !(problem_.depth > 0.0 && std::isfinite(problem_.depth))) {
    throw InputError("planar depth must be a finite number > 0 m");
  }
  for (const cases::RegionData& region : problem_.regions) {
    if (region.circuit >= static_cast<int>(problem_.circuits.size())) {
      throw InputError("a region refers to circuit " + std::to_string(region.circuit) + " but " +
                       std::to_string(problem_.circuits.size()) + " circuit(s) are defined");
    }
  }
  dofs_ = build_dof_map(mesh_, problem_);
  const bool robin = std::any_of(
      mesh_.boundary_edges.begin(), mesh_.boundary_edges.end(), [&](const mesh::BoundaryEdge& e) {
        return e.boundary >= 0 &&
               problem_.boundaries[e.boundary].kind == cases::BoundaryKind::mixed &&
               problem_.boundaries[e.boundary].c0 > 0.0;
      });
  if (dofs_.free_count() == static_cast<int>(mesh_.nodes.size()) && !robin && !dofs_.antiperiodic) {
    // Only axisymmetric models get here (planar ones have their gauge pinned): A_phi = C / r has
    // no field, so A is not determined.
    throw InputError(problem_.geometry.source +
                     ": A is not determined (axisymmetric model with no prescribed-A boundary, "
                     "no mixed boundary with c0 > 0 and no node on the axis: A = C/r carries no "
                     "field); add one, or use the automatic open outer boundary");
  }
  assembler_ = std::make_unique<Assembler>(problem_, mesh_, dofs_);
  linear_ = !assembler_->nonlinear();
  for (int c = 0; c < static_cast<int>(problem_.circuits.size()); ++c) {
    sources_.push_back(assembler_->circuit_source(c));
  }
  fixed_source_ = assembler_->fixed_source();
  for (const cases::PointCondition& point : problem_.point_conditions) {
    if (point.prescribed) continue;
    // A line current (planar: integral I delta v depth dA) or a ring current (2 pi r I v).
    const int node = mesh_node_at(mesh_, problem_, point.point);
    const double r = mesh_.nodes[node].r;
    fixed_source_[node] += point.current * (problem_.symmetry == cases::Symmetry::axisymmetric
                                                ? 2.0 * std::numbers::pi * r
                                                : problem_.depth);
  }
  if (dofs_.constrained()) {
    free_tangent_ = assembler_->pattern();
    // The reduced pattern: T^T K T of a K with every stored entry 1 (no cancellation).
    SparseMatrix ones = free_tangent_;
    std::fill(ones.valuePtr(), ones.valuePtr() + ones.nonZeros(), 1.0);
    tangent_ = reduce_tangent(ones);
    std::fill(tangent_.valuePtr(), tangent_.valuePtr() + tangent_.nonZeros(), 0.0);
  } else {
    tangent_ = assembler_->pattern();
  }
  if (dofs_.reduced_count() > 0) {
    use_huge_pages_for_cholmod();
    const SerialOpenMp serial;
    cholesky_.analyzePattern(tangent_);
    throw_if_out_of_memory(cholesky_);
    if (cholesky_.info() != Eigen::Success) {
      throw ConvergenceError("CHOLMOD symbolic analysis failed for " +
                             std::to_string(dofs_.reduced_count()) + " unknowns");
    }
  }
}

SparseMatrix MagnetostaticSolver::reduce_tangent(const SparseMatrix& lower) const {
  const SparseMatrix full = lower.selfadjointView<Eigen::Lower>();
  const SparseMatrix reduced = dofs_.reduction.transpose() * full * dofs_.reduction;
  return reduced.triangularView<Eigen::Lower>();
}

Eigen::VectorXd MagnetostaticSolver::reduced_to_nodes(const Eigen::VectorXd& x) const {
  return free_to_nodes(dofs_.expand(x));
}

Eigen::VectorXd MagnetostaticSolver::nodes_to_reduced(const Eigen::VectorXd& a) const {
  if (!dofs_.constrained()) return nodes_to_free(a);
  Eigen::VectorXd x(dofs_.reduced_count());
  for (int k = 0; k < dofs_.reduced_count(); ++k)
    x[k] = a[dofs_.node_of_dof[dofs_.free_of_reduced[k]]];
  return x;
}

Eigen::VectorXd MagnetostaticSolver::reduced_source(const Eigen::VectorXd& nodal) const {
  Eigen::VectorXd f(dofs_.free_count());
  for (int d = 0; d < dofs_.free_count(); ++d) f[d] = nodal[dofs_.node_of_dof[d]];
  return dofs_.reduce(f);
}

Eigen::VectorXd MagnetostaticSolver::free_to_nodes(const Eigen::VectorXd& x) const {
  Eigen::VectorXd a = Eigen::Map<const Eigen::VectorXd>(
      dofs_.fixed_value.data(), static_cast<Eigen::Index>(dofs_.fixed_value.size()));
  for (int d = 0; d < dofs_.free_count(); ++d) a[dofs_.node_of_dof[d]] = x[d];
  return a;
}

Eigen::VectorXd MagnetostaticSolver::nodes_to_free(const Eigen::VectorXd& a) const {
  Eigen::VectorXd x(dofs_.free_count());
  for (int d = 0; d < dofs_.free_count(); ++d) x[d] = a[dofs_.node_of_dof[d]];
  return x;
}

void MagnetostaticSolver::prepare_jacobian(const Eigen::VectorXd& a_nodes) {
  if (linear_ && factorized_linear_) {
    factor_current_ = true;
    return;
  }
  if (!(tangent_assembled_ && a_nodes.size() == tangent_nodes_.size() &&
        a_nodes == tangent_nodes_)) {
    Eigen::VectorXd r;
    assemble_residual_tangent(a_nodes, r);
  }
  if (dofs_.constrained()) {
    const SparseMatrix reduced = reduce_tangent(free_tangent_);
    if (reduced.nonZeros() != tangent_.nonZeros())
      throw ConvergenceError("periodic reduction changed the tangent's sparsity pattern");
    std::copy(reduced.valuePtr(), reduced.valuePtr() + reduced.nonZeros(), tangent_.valuePtr());
  }
  factor_current_ = false;
  // Tangent values more than kRefactorChange away from the factorised ones: far from the
  // solution the tangents differ too much (mostly at saturating corners) for a few CG iterations
  // to pay.
  const Eigen::Map<const Eigen::VectorXd> values(tangent_.valuePtr(), tangent_.nonZeros());
  const bool changed = !has_factor_ || (values - factored_values_).norm() >
                                           options_.reuse.refactor_change * factored_values_.norm();
  if (changed || refactor_next_ || linear_) factorize_tangent();
}

void MagnetostaticSolver::assemble_residual_tangent(const Eigen::VectorXd& a_nodes,
                                                    Eigen::VectorXd& r) {
  assembler_->assemble(a_nodes, r, dofs_.constrained() ? &free_tangent_ : &tangent_);
  tangent_nodes_ = a_nodes;
  tangent_assembled_ = true;
  ++assemblies_;
}

void MagnetostaticSolver::factorize_tangent() {
  const SerialOpenMp serial;
  cholesky_.factorize(tangent_);
  ++factorizations_;
  throw_if_out_of_memory(cholesky_);
  if (cholesky_.info() != Eigen::Success) {
    has_factor_ = false;
    throw ConvergenceError("CHOLMOD factorisation failed (tangent not positive definite, " +
                           std::to_string(dofs_.reduced_count()) + " unknowns)");
  }
  has_factor_ = factor_current_ = true;
  factored_values_ = Eigen::Map<const Eigen::VectorXd>(tangent_.valuePtr(), tangent_.nonZeros());
  refactor_next_ = false;
  factorized_linear_ = linear_;
}

Eigen::VectorXd MagnetostaticSolver::solve_jacobian(const Eigen::VectorXd& rhs, double tolerance,
                                                    double functional_tolerance) {
  if (factor_current_) return solve_factorized(rhs);
  Eigen::VectorXd x;
  const SerialOpenMp serial;
  const int budget = options_.reuse.max_iterations;
  const CgResult cg =
      preconditioned_cg(tangent_, cholesky_, rhs, tolerance, budget, x, functional_tolerance);
  reuse_iterations_ += cg.iterations;
  if (cg.converged && x.allFinite()) {
    if (2 * cg.iterations > budget) refactor_next_ = true;
    return x;
  }
  // The factor was too far from this tangent: factorise it, and factorise the next one directly
  // too (far from the solution consecutive tangents differ as much).
  factorize_tangent();
  refactor_next_ = true;
  return solve_factorized(rhs);
}

Eigen::VectorXd MagnetostaticSolver::solve_factorized(const Eigen::VectorXd& rhs) {
  const SerialOpenMp serial;
  Eigen::VectorXd x = cholesky_.solve(rhs);
  throw_if_out_of_memory(cholesky_);
  if (cholesky_.info() != Eigen::Success || !x.allFinite()) {
    throw ConvergenceError("CHOLMOD triangular solve failed");
  }
  return x;
}

Eigen::VectorXd MagnetostaticSolver::residual(const Eigen::VectorXd& a,
                                              const std::vector<double>& currents) const {
  Eigen::VectorXd r;
  assembler_->assemble(a, r, nullptr);
  const Eigen::VectorXd f = nodal_source(currents);
  for (int d = 0; d < dofs_.free_count(); ++d) r[d] -= f[dofs_.node_of_dof[d]];
  return r;
}

Eigen::VectorXd MagnetostaticSolver::residual(const Eigen::VectorXd& a,
                                              const std::vector<double>& currents,
                                              SparseMatrix& tangent) const {
  tangent = assembler_->pattern();
  Eigen::VectorXd r;
  assembler_->assemble(a, r, &tangent);
  const Eigen::VectorXd f = nodal_source(currents);
  for (int d = 0; d < dofs_.free_count(); ++d) r[d] -= f[dofs_.node_of_dof[d]];
  return r;
}

std::shared_ptr<const FrozenFactor> MagnetostaticSolver::freeze_tangent_factor() {
  if (dofs_.reduced_count() == 0 || !tangent_assembled_) return nullptr;
  if (!factor_current_) factorize_tangent();
  return std::make_shared<const FrozenFactor>(*cholesky_.factor());
}

SparseMatrix MagnetostaticSolver::tangent(const Eigen::VectorXd& a) const {
  SparseMatrix k = assembler_->pattern();
  Eigen::VectorXd r;
  assembler_->assemble(a, r, &k);
  return k;
}

Solution MagnetostaticSolver::solve() {
  std::vector<double> currents;
  for (const cases::Circuit& c : problem_.circuits) currents.push_back(c.current);
  return solve(currents);
}

Solution MagnetostaticSolver::solve(const std::vector<double>& currents,
                                    const Eigen::VectorXd* initial_guess) {
  return solve_with(currents, initial_guess, options_.incremental_inductance);
}

Solution MagnetostaticSolver::solve_incremental(const std::vector<double>& currents,
                                                const Eigen::VectorXd* initial_guess) {
  return solve_with(currents, initial_guess, true, initial_guess == nullptr);
}

const Eigen::VectorXd& MagnetostaticSolver::zero_field_load() {
  if (!zero_field_load_) {
    Eigen::VectorXd r;
    assembler_->assemble(reduced_to_nodes(Eigen::VectorXd::Zero(dofs_.reduced_count())), r,
                         nullptr);
    ++assemblies_;
    if (dofs_.constrained()) r = dofs_.reduce(r);
    zero_field_load_ = std::move(r);
  }
  return *zero_field_load_;
}

Solution MagnetostaticSolver::solve_with(const std::vector<double>& currents,
                                         const Eigen::VectorXd* initial_guess, bool incremental,
                                         bool local_corrections) {
  const auto start = std::chrono::steady_clock::now();
  if (currents.size() != problem_.circuits.size()) {
    throw InputError(std::to_string(currents.size()) + " current(s) given for " +
                     std::to_string(problem_.circuits.size()) + " circuit(s)");
  }
  for (double current : currents) {
    if (!std::isfinite(current)) throw InputError("circuit current is not a finite number");
  }
  const int n = dofs_.reduced_count();
  const Eigen::VectorXd nodal = nodal_source(currents);
  if (dofs_.gauge_node >= 0) check_compatible(nodal);
  System system(*this, reduced_source(nodal));
  tangent_assembled_ = false;  // an earlier solve's tangent (the mesh may have moved since)
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), r;
  const double scale = system.residual_at_zero(r);
  // Finite currents whose load overflows (1e300 A through the turns): Newton reported "the
  // residual diverged ... reached -nan", which does not say why.
  if (!std::isfinite(scale)) {
    double largest = 0.0;
    for (double current : currents) largest = std::max(largest, std::abs(current));
    std::ostringstream message;
    message << "the source of the field equation is not a finite number: the circuit currents "
               "(largest "
            << largest
            << " A) times the turns, a fixed current density or a magnet's coercivity is beyond "
               "double arithmetic";
    throw ConvergenceError(message.str());
  }
  if (initial_guess) {
    x = nodes_to_reduced(*initial_guess);
  } else {
    system.remember(x, r);
  }

  Solution solution;
  solution.currents = currents;
  // A warm-started incremental solve (sweeps, quasi-static tables): its few steps are rarely
  // moved by local corrections (which would waste the tangent at the iterate they move), and
  // dlambda/dI takes the tangent at the solution. A plain solve would assemble that tangent for
  // nothing.
  if (incremental && initial_guess) system.assemble_tangents();
  NewtonOptions newton = options_.newton;
  if (!local_corrections) newton.local_iterations = 0;
  solution.newton = newton_solve(system, x, scale, newton);
  solution.a = reduced_to_nodes(x);
  for (const Eigen::VectorXd& f : sources_) solution.flux_linkage.push_back(f.dot(solution.a));
  if (incremental && n > 0) {
    system.residual(x, solution.residual);  // Newton's last evaluation: no assembly
    // dlambda_c/dI_c = F_c^T K_t^{-1} F_c with K_t the exact tangent at the solution, to 1e-12
    // relative (CG's error of F.x, r.K^-1.r, below 1e-12 F.x, or a residual below 1e-12).
    if (factorise_incremental_) refactor_next_ = true;
    prepare_jacobian(solution.a);
    for (const Eigen::VectorXd& f : sources_) {
      const Eigen::VectorXd f_reduced = reduced_source(f);
      solution.incremental_field.push_back(solve_jacobian(f_reduced, 1e-12, 1e-12));
      solution.incremental_inductance.push_back(f_reduced.dot(solution.incremental_field.back()));
    }
  }
  solution.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return solution;
}

std::vector<SweepPoint> MagnetostaticSolver::sweep(
    int circuit, const std::vector<double>& currents,
    const std::function<void(const Solution&, SweepPoint&)>& each) {
  if (circuit < 0 || circuit >= static_cast<int>(problem_.circuits.size())) {
    throw InputError("sweep of circuit " + std::to_string(circuit) + " but " +
                     std::to_string(problem_.circuits.size()) + " circuit(s) are defined");
  }
  std::vector<double> present;
  for (const cases::Circuit& c : problem_.circuits) present.push_back(c.current);
  std::vector<SweepPoint> table;
  Eigen::VectorXd previous;
  for (double current : currents) {
    present[circuit] = current;
    Solution s = solve_with(present, previous.size() ? &previous : nullptr, true);
    SweepPoint point;
    point.current = current;
    point.flux_linkage = s.flux_linkage[circuit];
    point.incremental_inductance = s.incremental_inductance[circuit];
    point.secant_inductance =
        current != 0.0 ? point.flux_linkage / current : point.incremental_inductance;
    point.newton_iterations = s.newton.iterations;
    if (each) each(s, point);
    table.push_back(point);
    previous = std::move(s.a);
  }
  return table;
}

Eigen::VectorXd MagnetostaticSolver::nodal_source(const std::vector<double>& currents) const {
  Eigen::VectorXd f = fixed_source_;
  for (std::size_t c = 0; c < currents.size() && c < sources_.size(); ++c)
    f += currents[c] * sources_[c];
  return f;
}

void MagnetostaticSolver::check_compatible(const Eigen::VectorXd& nodal) const {
  // With dA/dn = 0 on the whole boundary, integral nu dA/dn ds = 0 = the net current: the sum
  // of all nodal sources (each is integral J N_i dV, sum_i N_i = 1; magnets add nothing).
  const double net = nodal.sum(), scale = nodal.cwiseAbs().sum();
  if (std::abs(net) <= 1e-9 * scale) return;
  std::ostringstream msg;
  msg << problem_.geometry.source << ": the net current through the model is "
      << net / problem_.depth
      << " A but no boundary carries flux out of it (no prescribed-A boundary, no mixed boundary "
         "with c0 > 0: dA/dn = 0 everywhere, FEMM's default on edges without a condition): no "
         "field satisfies this; add a return conductor or a boundary condition";
  throw InputError(msg.str());
}

bool MagnetostaticSolver::flux_linkage_gauge_free(int c) const {
  if (dofs_.gauge_node < 0) return true;
  const Eigen::VectorXd& f = sources_[c];
  return std::abs(f.sum()) <= 1e-9 * f.cwiseAbs().sum();
}

void MagnetostaticSolver::discard_factorisation() {
  has_factor_ = factor_current_ = factorized_linear_ = false;
  refactor_next_ = true;
}

}  // namespace rheomag::magnetostatics
