#include "magnetostatics3d/discrete_gradient.hpp"

#include <vector>

namespace rheomag::magnetostatics3d {

Eigen::SparseMatrix<double, Eigen::RowMajor, int> discrete_gradient(const TetMesh& mesh) {
  std::vector<Eigen::Triplet<double, int>> entries;
  entries.reserve(2 * mesh.edges.size());
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    entries.emplace_back(static_cast<int>(e), mesh.edges[e][0], -1.0);
    entries.emplace_back(static_cast<int>(e), mesh.edges[e][1], 1.0);
  }
  Eigen::SparseMatrix<double, Eigen::RowMajor, int> g(static_cast<int>(mesh.edges.size()),
                                                      static_cast<int>(mesh.nodes.size()));
  g.setFromTriplets(entries.begin(), entries.end());
  return g;
}

double relative_divergence(const Eigen::SparseMatrix<double, Eigen::RowMajor, int>& gradient,
                           const Eigen::VectorXd& f) {
  const double norm = f.norm();
  return norm > 0.0 ? (gradient.transpose() * f).norm() / norm : 0.0;
}

}  // namespace rheomag::magnetostatics3d
