#include "magnetostatics3d/body_force.hpp"

#include <stdexcept>

#include "core/constants.hpp"

namespace rheomag::magnetostatics3d {

Eigen::Vector3d body_force(const TetMesh& mesh, const std::vector<Eigen::Vector3d>& b,
                           const std::vector<bool>& in_body, const std::vector<bool>& is_air) {
  std::vector<bool> body_node(mesh.nodes.size(), false);
  for (std::size_t t = 0; t < mesh.tets.size(); ++t)
    if (in_body[mesh.region[t]])
      for (int v : mesh.tets[t]) body_node[v] = true;
  Eigen::Vector3d force = Eigen::Vector3d::Zero();
  for (int t = 0; t < static_cast<int>(mesh.tets.size()); ++t) {
    if (in_body[mesh.region[t]]) continue;  // g = 1 on all its nodes: grad g = 0
    const auto& v = mesh.tets[t];
    Eigen::Vector3d grad_g = Eigen::Vector3d::Zero();
    bool touches = false;
    const auto grads = mesh.gradients(t);
    for (int k = 0; k < 4; ++k)
      if (body_node[v[k]]) {
        grad_g += grads[k];
        touches = true;
      }
    if (!touches) continue;
    if (!is_air[mesh.region[t]]) {
      throw std::logic_error("body_force: the body touches a region that is not air");
    }
    const Eigen::Vector3d& bt = b[t];
    const Eigen::Vector3d stress_g = (bt * bt.dot(grad_g) - 0.5 * bt.squaredNorm() * grad_g) / kMu0;
    force -= std::abs(mesh.volume(t)) * stress_g;
  }
  return force;
}

}  // namespace rheomag::magnetostatics3d
