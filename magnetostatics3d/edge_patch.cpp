#include "magnetostatics3d/edge_patch.hpp"

#include <algorithm>

namespace rheomag::magnetostatics3d {

EdgeTetrahedra edge_tetrahedra(const TetMesh& mesh) {
  EdgeTetrahedra out;
  out.start.assign(mesh.edges.size() + 1, 0);
  for (const auto& edges : mesh.tet_edges)
    for (int e : edges) ++out.start[e + 1];
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) out.start[e + 1] += out.start[e];
  out.tets.resize(out.start.back());
  std::vector<int> next(out.start.begin(), out.start.end() - 1);
  for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t)
    for (int e : mesh.tet_edges[t]) out.tets[next[e]++] = t;  // ascending t per edge
  return out;
}

EdgePatch::EdgePatch(const EdgeSolver& solver, const EdgeTetrahedra& around,
                     const Eigen::VectorXd& load, Eigen::VectorXd& x, Eigen::VectorXd& a,
                     const std::vector<int>& seeds, int layers, bool regularise)
    : solver_(solver), load_(load), x_(x), a_(a), regularise_(regularise) {
  const TetMesh& mesh = solver.mesh();
  const EdgeDofs& dofs = solver.dofs();
  local_row_.assign(static_cast<std::size_t>(dofs.free_count()), -1);
  std::vector<int> unknowns;
  auto add = [&](int d) {
    if (d >= 0 && local_row_[d] < 0) unknowns.push_back(d), local_row_[d] = 0;
  };
  for (int d : seeds) add(d);
  std::size_t ring_begin = 0;
  for (int layer = 0; layer < layers; ++layer) {
    const std::size_t ring_end = unknowns.size();
    for (std::size_t k = ring_begin; k < ring_end; ++k) {
      const int e = dofs.edge_of_dof[unknowns[k]];
      for (int s = around.start[e]; s < around.start[e + 1]; ++s)
        for (int e2 : mesh.tet_edges[around.tets[s]]) add(dofs.dof_of_edge[e2]);
    }
    ring_begin = ring_end;
  }
  std::sort(unknowns.begin(), unknowns.end());
  std::vector<char> element_in(mesh.tets.size(), 0);
  for (int d : unknowns) {
    const int e = dofs.edge_of_dof[d];
    for (int s = around.start[e]; s < around.start[e + 1]; ++s) {
      if (!element_in[around.tets[s]]) elements_.push_back(around.tets[s]);
      element_in[around.tets[s]] = 1;
    }
  }
  std::sort(elements_.begin(), elements_.end());
  unknowns_ = static_cast<int>(unknowns.size());
  rows_ = std::move(unknowns);
  for (int k = 0; k < unknowns_; ++k) local_row_[rows_[k]] = k;
  for (int t : elements_) {
    for (int e : mesh.tet_edges[t]) {
      const int d = dofs.dof_of_edge[e];
      if (d >= 0 && local_row_[d] < 0) {
        local_row_[d] = static_cast<int>(rows_.size());
        rows_.push_back(d);
      }
    }
  }
}

Eigen::VectorXd EdgePatch::values() const {
  Eigen::VectorXd v(unknowns_);
  for (int k = 0; k < unknowns_; ++k) v[k] = x_[rows_[k]];
  return v;
}

void EdgePatch::set_values(const Eigen::VectorXd& values) {
  const EdgeDofs& dofs = solver_.dofs();
  for (int k = 0; k < unknowns_; ++k) {
    x_[rows_[k]] = values[k];
    a_[dofs.edge_of_dof[rows_[k]]] = values[k];
  }
}

void EdgePatch::assemble(Eigen::VectorXd& internal,
                         Eigen::SparseMatrix<double, Eigen::ColMajor, int>* tangent) const {
  const TetMesh& mesh = solver_.mesh();
  const EdgeDofs& dofs = solver_.dofs();
  internal.setZero(static_cast<Eigen::Index>(rows_.size()));
  std::vector<Eigen::Triplet<double, int>> entries;
  if (tangent) entries.reserve(elements_.size() * 21);
  for (int t : elements_) {
    const Eigen::Vector3d b = solver_.flux_density(t, a_);
    const double b2 = b.squaredNorm();
    const magnetostatics::Reluctivity& law = solver_.law(t);
    const double v = solver_.volume(t), n = law.nu(b2);
    const auto& c = solver_.curls(t);
    std::array<int, 6> row;
    std::array<double, 6> bc;
    for (int i = 0; i < 6; ++i) {
      const int d = dofs.dof_of_edge[mesh.tet_edges[t][i]];
      row[i] = d >= 0 ? local_row_[d] : -1;
      bc[i] = b.dot(c[i]);
      if (row[i] >= 0) internal[row[i]] += v * n * bc[i];
    }
    if (!tangent) continue;
    const double dn = 2.0 * law.dnu_db2(b2);
    for (int i = 0; i < 6; ++i) {
      if (row[i] < 0 || row[i] >= unknowns_) continue;
      for (int j = 0; j < 6; ++j) {
        if (row[j] < 0 || row[j] > row[i]) continue;
        entries.emplace_back(row[i], row[j], v * (n * c[i].dot(c[j]) + dn * bc[i] * bc[j]));
      }
    }
  }
  if (!tangent) return;
  tangent->resize(unknowns_, unknowns_);
  tangent->setFromTriplets(entries.begin(), entries.end());
  if (regularise_)
    for (int k = 0; k < unknowns_; ++k) tangent->coeffRef(k, k) *= 1.0 + 1e-8;
}

double EdgePatch::potential() const {
  double energy = 0.0;
  for (int t : elements_)
    energy += solver_.volume(t) *
              solver_.law(t).energy_density(solver_.flux_density(t, a_).squaredNorm());
  double work = 0.0;
  for (int k = 0; k < unknowns_; ++k) work += load_[rows_[k]] * x_[rows_[k]];
  return energy - work;
}

}  // namespace rheomag::magnetostatics3d
