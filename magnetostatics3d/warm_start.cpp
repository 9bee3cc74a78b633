#include "magnetostatics3d/warm_start.hpp"

#include <cmath>

#include "core/error.hpp"
#include "magnetostatics/prolongation.hpp"
#include "magnetostatics/solver.hpp"

namespace rheomag::magnetostatics3d {
namespace {

/// Gauss points of the two-point rule on [0, 1] (weights 1/2 each).
constexpr double kGauss[2] = {0.5 - 0.5 / 1.7320508075688772, 0.5 + 0.5 / 1.7320508075688772};

}  // namespace

Eigen::VectorXd revolved_edge_values(const TetMesh& mesh, const mesh::Mesh& meridian,
                                     const Eigen::VectorXd& a_phi) {
  // The Gauss points as the nodes of a point set located in the meridian mesh in one pass.
  mesh::Mesh points;
  points.nodes.reserve(2 * mesh.edges.size());
  for (const auto& [p, q] : mesh.edges) {
    for (double s : kGauss) {
      const Eigen::Vector3d x = (1.0 - s) * mesh.nodes[p] + s * mesh.nodes[q];
      points.nodes.push_back({std::hypot(x.x(), x.y()), x.z()});
    }
  }
  points.vertex_count = static_cast<int>(points.nodes.size());
  const Eigen::VectorXd at_points = magnetostatics::interpolate_nodal(meridian, a_phi, points);
  Eigen::VectorXd values(static_cast<Eigen::Index>(mesh.edges.size()));
  for (std::size_t e = 0; e < mesh.edges.size(); ++e) {
    const Eigen::Vector3d& p = mesh.nodes[mesh.edges[e][0]];
    const Eigen::Vector3d& q = mesh.nodes[mesh.edges[e][1]];
    const Eigen::Vector3d dx = q - p;
    double sum = 0.0;
    for (int g = 0; g < 2; ++g) {
      const Eigen::Vector3d x = (1.0 - kGauss[g]) * p + kGauss[g] * q;
      const double r = std::hypot(x.x(), x.y());
      if (r <= 0.0) continue;  // on the axis A_phi = 0
      const Eigen::Vector3d e_phi(-x.y() / r, x.x() / r, 0.0);
      sum += 0.5 * at_points[static_cast<Eigen::Index>(2 * e + g)] * e_phi.dot(dx);
    }
    values[static_cast<Eigen::Index>(e)] = sum;
  }
  return values;
}

Eigen::VectorXd revolved_2d_solution(const cases::Problem& closed, const mesh::Mesh& meridian,
                                     const TetMesh& mesh) {
  magnetostatics::SolveOptions options;
  options.incremental_inductance = false;  // only A is needed
  try {
    magnetostatics::MagnetostaticSolver two(closed, meridian, options);
    return revolved_edge_values(mesh, meridian, two.solve().a);
  } catch (const ConvergenceError&) {
    return {};
  }
}

}  // namespace rheomag::magnetostatics3d
