#include "magnetostatics3d/edge_solver.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/format_text.hpp"
#include "magnetostatics/cholmod_status.hpp"
#include "magnetostatics/preconditioned_cg.hpp"
#include "magnetostatics/serial_openmp.hpp"
#include "magnetostatics3d/ams_solver.hpp"
#include "magnetostatics3d/edge_patch.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// Unknowns from which the tangent is ordered by METIS alone (nested dissection). CHOLMOD's
/// default computes AMD first and METIS only when AMD fills in much; on 3D edge systems METIS
/// always won there (3.0x fewer flops at 127k unknowns, 4.7x at 342k), so AMD was time lost
/// (about 1 s at 342k). Below it the default stays: it keeps AMD where that wins, as on the
/// nearly flat swept wedge (one prism layer, 15k unknowns).
constexpr int kNestedDissectionUnknowns = 50000;

}  // namespace

/// R(x) = grad E(x) over the unknowns (cotree or all free edges) at fixed currents.
class EdgeSolver::System : public magnetostatics::NonlinearSystem {
 public:
  System(EdgeSolver& solver, Eigen::VectorXd load) : s_(solver), load_(std::move(load)) {}
  double residual(const Eigen::VectorXd& x, Eigen::VectorXd& r) override {
    s_.assemble(s_.to_edges(x), &r, false);
    r -= load_;
    return r.norm();
  }
  void factorize_jacobian(const Eigen::VectorXd& x) override {
    // Linear: one factorisation (AMS set-up) for all steps and solves.
    factor_current_ = s_.factorized_ && !s_.nonlinear_;
    if (factor_current_) return;
    s_.assemble(s_.to_edges(x), nullptr, true);
    if (s_.linear_ == LinearSolver3d::ams) {
      // A set-up per step: one kept from an earlier step cost more CG iterations than its
      // set-up (docs/magnetostatics3d.md).
      s_.ams_->set_matrix(s_.tangent_);
      s_.factorized_ = factor_current_ = true;
      ++s_.factorizations_;
      return;
    }
    // With a budget for CG, only the first step factorises; the others try the old factor.
    if (!s_.factorized_ || s_.reuse_iterations_ == 0) factorize();
  }
  Eigen::VectorXd solve_jacobian(const Eigen::VectorXd& rhs, double tolerance) override {
    if (s_.linear_ == LinearSolver3d::ams) return solve_ams(rhs, tolerance);
    const magnetostatics::SerialOpenMp serial;
    if (!factor_current_) {
      Eigen::VectorXd x;
      const magnetostatics::CgResult cg = magnetostatics::preconditioned_cg(
          s_.tangent_, s_.cholesky_, rhs, tolerance, s_.reuse_iterations_, x);
      s_.cg_iterations_ += cg.iterations;
      if (cg.converged && x.allFinite()) return x;
      factorize();  // the old factor is too far from this tangent
    }
    return s_.cholesky_.solve(rhs);
  }
  int correct_locally(Eigen::VectorXd& x, Eigen::VectorXd& r, double& norm) override {
    if (!s_.nonlinear_) return 0;
    Eigen::VectorXd a = s_.to_edges(x);
    const bool regularise = s_.linear_ == LinearSolver3d::ams;
    const magnetostatics::PatchBuilder build = [&](const std::vector<int>& seeds, int layers) {
      return std::make_unique<EdgePatch>(s_, *s_.around_, load_, x, a, seeds, layers, regularise);
    };
    return magnetostatics::correct_locally(build, s_.options_, r, norm);
  }
  double energy(const Eigen::VectorXd& x) override {
    const Eigen::VectorXd a = s_.to_edges(x);
    std::vector<Eigen::Vector3d> b(s_.mesh_.tets.size());
    for (std::size_t t = 0; t < b.size(); ++t) b[t] = s_.flux_density(static_cast<int>(t), a);
    return s_.stored_energy(b) - load_.dot(x);
  }

 private:
  /// AMS-preconditioned CG over the edges (fixed edges: zero) to the tolerance.
  Eigen::VectorXd solve_ams(const Eigen::VectorXd& rhs, double tolerance) {
    const EdgeDofs& dofs = s_.dofs_;
    Eigen::VectorXd b = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(dofs.fixed.size())), a;
    for (int d = 0; d < dofs.free_count(); ++d) b[dofs.edge_of_dof[d]] = rhs[d];
    const magnetostatics::CgResult cg = s_.ams_->solve(b, tolerance, kAmsMaxIterations, a);
    s_.cg_iterations_ += cg.iterations;
    if (!cg.converged || !a.allFinite())
      throw ConvergenceError("AMS-preconditioned CG did not reach the relative residual " +
                             format_text("%.1e", tolerance) + " in " +
                             std::to_string(kAmsMaxIterations) + " iterations");
    Eigen::VectorXd x(dofs.free_count());
    for (int d = 0; d < dofs.free_count(); ++d) x[d] = a[dofs.edge_of_dof[d]];
    return x;
  }

  void factorize() {
    const magnetostatics::SerialOpenMp serial;
    s_.cholesky_.factorize(s_.tangent_);
    magnetostatics::throw_if_out_of_memory(s_.cholesky_);
    if (s_.cholesky_.info() != Eigen::Success) {
      throw ConvergenceError("CHOLMOD could not factorise the 3D tangent (not positive definite)");
    }
    s_.factorized_ = factor_current_ = true;
    ++s_.factorizations_;
  }

  static constexpr int kAmsMaxIterations = 1000;
  EdgeSolver& s_;
  Eigen::VectorXd load_;         // over the unknowns, at the solve's currents
  bool factor_current_ = false;  // the factorisation is of the tangent last assembled
};

EdgeSolver::EdgeSolver(const TetMesh& mesh, std::vector<magnetostatics::Reluctivity> laws,
                       std::vector<int> material_of_region, Eigen::VectorXd fixed_values,
                       std::vector<Eigen::VectorXd> loads, magnetostatics::NewtonOptions options,
                       int reuse_iterations, LinearSolver3d linear)
    : mesh_(mesh),
      laws_(std::move(laws)),
      material_of_region_(std::move(material_of_region)),
      fixed_values_(std::move(fixed_values)),
      loads_(std::move(loads)),
      options_(options),
      linear_(linear),
      reuse_iterations_(reuse_iterations) {
  for (int m : material_of_region_) {
    if (m < 0 || m >= static_cast<int>(laws_.size()))
      throw InputError("3D mesh: a region has no material");
    nonlinear_ = nonlinear_ || laws_[m].nonlinear();
  }
  dofs_ = linear_ == LinearSolver3d::ams ? free_edge_dofs(mesh_) : tree_cotree_dofs(mesh_);
  const int n_tets = static_cast<int>(mesh_.tets.size());
  volume_.resize(n_tets);
  curl_.resize(n_tets);
  for (int t = 0; t < n_tets; ++t) {
    volume_[t] = mesh_.volume(t);
    curl_[t] = edge_curls(mesh_, t);
  }
  around_ = std::make_unique<EdgeTetrahedra>(edge_tetrahedra(mesh_));
  build_pattern();
  if (linear_ == LinearSolver3d::ams) {
    ams_ = std::make_unique<AmsCg>(mesh_, dofs_.fixed);
  } else if (dofs_.free_count() > 0) {
    const magnetostatics::SerialOpenMp serial;
    cholmod_common& common = cholesky_.cholmod();
    if (tangent_.rows() >= kNestedDissectionUnknowns) {
      common.nmethods = 1;
      common.method[0].ordering = CHOLMOD_METIS;
    }
    cholesky_.analyzePattern(tangent_);
    if (common.status == CHOLMOD_NOT_INSTALLED && common.nmethods == 1) {
      common.nmethods = 0;  // a CHOLMOD built without METIS: its default orderings
      common.status = CHOLMOD_OK;
      cholesky_.analyzePattern(tangent_);
    }
    magnetostatics::throw_if_out_of_memory(cholesky_);
    if (cholesky_.info() != Eigen::Success)
      throw ConvergenceError("CHOLMOD symbolic analysis failed for " +
                             std::to_string(dofs_.free_count()) + " unknowns");
  }
}

EdgeSolver::~EdgeSolver() = default;

int EdgeSolver::row_of(int edge) const {
  return linear_ == LinearSolver3d::ams ? edge : dofs_.dof_of_edge[edge];
}

void EdgeSolver::build_pattern() {
  // The pattern of the tangent, then each element entry's value slot. An entry couples two
  // unknowns (CHOLMOD: the lower triangle); with AMS a fixed edge also keeps its diagonal (its
  // row and column eliminated as MFEM does, the element's diagonal kept for the scale).
  const bool full = linear_ == LinearSolver3d::ams;
  const int n = full ? static_cast<int>(mesh_.edges.size()) : dofs_.free_count();
  const int n_tets = static_cast<int>(mesh_.tets.size());
  // Calls f(i, j, row, column) for every entry of tetrahedron t.
  auto for_entries = [&](int t, auto&& f) {
    std::array<int, 6> row;
    std::array<bool, 6> free;
    for (int i = 0; i < 6; ++i) {
      const int e = mesh_.tet_edges[t][i];
      row[i] = row_of(e);
      free[i] = dofs_.dof_of_edge[e] >= 0;
    }
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j < 6; ++j) {
        if (row[i] < 0 || row[j] < 0 || !((free[i] && free[j]) || i == j)) continue;
        if (!full && row[j] > row[i]) continue;
        f(i, j, row[i], row[j]);
      }
    }
  };
  // The rows of every element entry, bucketed by column, then each column sorted and made
  // unique (one sort of all the entries, 12.6 million on the lead-slot half model, took 1.5 s).
  std::vector<int> outer(n + 1, 0), inner;
  for (int t = 0; t < n_tets; ++t) for_entries(t, [&](int, int, int, int c) { ++outer[c + 1]; });
  for (int c = 0; c < n; ++c) outer[c + 1] += outer[c];
  inner.resize(outer[n]);
  std::vector<int> next(outer.begin(), outer.end() - 1);
  for (int t = 0; t < n_tets; ++t)
    for_entries(t, [&](int, int, int r, int c) { inner[next[c]++] = r; });
  int kept = 0;
  for (int c = 0; c < n; ++c) {
    const auto begin = inner.begin() + outer[c], end = inner.begin() + outer[c + 1];
    std::sort(begin, end);
    const int unique = static_cast<int>(std::unique(begin, end) - begin);
    std::copy(begin, begin + unique, inner.begin() + kept);
    outer[c] = kept;
    kept += unique;
  }
  outer[n] = kept;
  tangent_.resize(n, n);
  tangent_.resizeNonZeros(kept);
  std::copy(outer.begin(), outer.end(), tangent_.outerIndexPtr());
  std::copy(inner.begin(), inner.begin() + kept, tangent_.innerIndexPtr());
  std::fill(tangent_.valuePtr(), tangent_.valuePtr() + kept, 0.0);
  slot_.assign(n_tets, {});
  for (int t = 0; t < n_tets; ++t) {
    slot_[t].fill(-1);
    for_entries(t, [&](int i, int j, int r, int c) {
      const int* begin = tangent_.innerIndexPtr() + tangent_.outerIndexPtr()[c];
      const int* end = tangent_.innerIndexPtr() + tangent_.outerIndexPtr()[c + 1];
      slot_[t][6 * i + j] =
          static_cast<int>(std::lower_bound(begin, end, r) - tangent_.innerIndexPtr());
    });
  }
}

Eigen::VectorXd EdgeSolver::to_edges(const Eigen::VectorXd& x) const {
  Eigen::VectorXd a = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh_.edges.size()));
  for (std::size_t e = 0; e < mesh_.edges.size(); ++e)
    if (dofs_.fixed[e]) a[e] = fixed_values_[e];
  for (int d = 0; d < dofs_.free_count(); ++d) a[dofs_.edge_of_dof[d]] = x[d];
  return a;
}

Eigen::Vector3d EdgeSolver::flux_density(int t, const Eigen::VectorXd& a) const {
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  for (int e = 0; e < 6; ++e) b += a[mesh_.tet_edges[t][e]] * curl_[t][e];
  return b;
}

double EdgeSolver::stored_energy(const std::vector<Eigen::Vector3d>& b) const {
  double w = 0.0;
  for (std::size_t t = 0; t < b.size(); ++t)
    w += volume_[t] * law(static_cast<int>(t)).energy_density(b[t].squaredNorm());
  return w;
}

void EdgeSolver::assemble(const Eigen::VectorXd& a, Eigen::VectorXd* residual, bool tangent) {
  if (residual) residual->setZero(dofs_.free_count());
  if (tangent) std::fill(tangent_.valuePtr(), tangent_.valuePtr() + tangent_.nonZeros(), 0.0);
  for (int t = 0; t < static_cast<int>(mesh_.tets.size()); ++t) {
    const Eigen::Vector3d b = flux_density(t, a);
    const double b2 = b.squaredNorm();
    const magnetostatics::Reluctivity& nu = law(t);
    const double v = volume_[t], n = nu.nu(b2);
    const auto& c = curl_[t];
    if (residual) {
      for (int i = 0; i < 6; ++i) {
        const int d = dofs_.dof_of_edge[mesh_.tet_edges[t][i]];
        if (d >= 0) (*residual)[d] += v * n * b.dot(c[i]);
      }
    }
    if (!tangent) continue;
    const double dn = 2.0 * nu.dnu_db2(b2);
    std::array<double, 6> bc;
    for (int i = 0; i < 6; ++i) bc[i] = b.dot(c[i]);
    for (int i = 0; i < 6; ++i) {
      for (int j = 0; j <= i; ++j) {
        const double k = v * (n * c[i].dot(c[j]) + dn * bc[i] * bc[j]);
        const int s1 = slot_[t][6 * i + j], s2 = slot_[t][6 * j + i];
        // CHOLMOD: one of (i, j), (j, i) is in the lower triangle; AMS: both are stored. The
        // diagonal appears once.
        if (s1 >= 0) tangent_.valuePtr()[s1] += k;
        if (s2 >= 0 && i != j) tangent_.valuePtr()[s2] += k;
      }
    }
  }
}

EdgeSolution EdgeSolver::solve(const std::vector<double>& currents) {
  return solve(currents, Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh_.edges.size())));
}

EdgeSolution EdgeSolver::solve(const std::vector<double>& currents, const Eigen::VectorXd& start) {
  const auto start_time = std::chrono::steady_clock::now();
  const int factorizations_before = factorizations_, cg_before = cg_iterations_;
  EdgeSolution sol;
  sol.currents = currents;
  const int n = dofs_.free_count();
  Eigen::VectorXd load_edges = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(mesh_.edges.size()));
  for (std::size_t c = 0; c < currents.size() && c < loads_.size(); ++c)
    load_edges += currents[c] * loads_[c];
  Eigen::VectorXd load(n);
  for (int d = 0; d < n; ++d) load[d] = load_edges[dofs_.edge_of_dof[d]];
  System system(*this, load);
  // Reference of the relative residual: the residual at x = 0 (fixed values and loads), whatever
  // the start, so that a warm start converges to the same tolerance.
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n), r;
  const double scale = system.residual(x, r);
  if (start.size() == static_cast<Eigen::Index>(mesh_.edges.size()) && !start.isZero(0.0)) {
    if (linear_ == LinearSolver3d::ams) {
      for (int d = 0; d < n; ++d) x[d] = start[dofs_.edge_of_dof[d]];  // no gauge to remove
    } else {
      x = cotree_values(mesh_, dofs_, start);
    }
  }
  sol.newton = magnetostatics::newton_solve(system, x, scale, options_);
  sol.factorizations = factorizations_ - factorizations_before;
  sol.cg_iterations = cg_iterations_ - cg_before;
  sol.a = to_edges(x);
  sol.b.resize(mesh_.tets.size());
  for (std::size_t t = 0; t < sol.b.size(); ++t)
    sol.b[t] = flux_density(static_cast<int>(t), sol.a);
  sol.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start_time).count();
  return sol;
}

}  // namespace rheomag::magnetostatics3d
