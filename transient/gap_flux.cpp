#include "transient/gap_flux.hpp"

#include <cmath>

#include "magnetostatics/element_kernel.hpp"

namespace rheomag::transient {

std::vector<int> gap_regions(const magnetostatics::MagnetostaticSolver& statics) {
  std::vector<int> out;
  const auto& seeds = statics.problem().geometry.regions;
  for (int k = 0; k < static_cast<int>(seeds.size()); ++k)
    if (seeds[k].gap != mesh::GapKind::none) out.push_back(k);
  return out;
}

std::vector<double> region_mean_b(const magnetostatics::MagnetostaticSolver& statics,
                                  const std::vector<int>& regions, const Eigen::VectorXd& a) {
  const mesh::Mesh& m = statics.mesh();
  std::vector<int> slot(statics.problem().regions.size(), -1);
  for (std::size_t k = 0; k < regions.size(); ++k) slot[regions[k]] = static_cast<int>(k);
  std::vector<double> sum(regions.size(), 0.0), area(regions.size(), 0.0);
  magnetostatics::ElementQuadrature q;
  double a_local[magnetostatics::kMaxElementNodes];
  for (int e = 0; e < static_cast<int>(m.triangles.size()); ++e) {
    const int k = slot[m.region[e]];
    if (k < 0) continue;
    statics.assembler().quadrature(e, q);
    for (int i = 0; i < q.nodes; ++i) a_local[i] = a[m.triangles[e][i]];
    for (int p = 0; p < q.points; ++p) {
      const auto b = magnetostatics::element_b(q, p, a_local);
      sum[k] += q.area_weight[p] * std::hypot(b[0], b[1]);
      area[k] += q.area_weight[p];
    }
  }
  for (std::size_t k = 0; k < regions.size(); ++k) sum[k] = area[k] > 0.0 ? sum[k] / area[k] : 0.0;
  return sum;
}

}  // namespace rheomag::transient
