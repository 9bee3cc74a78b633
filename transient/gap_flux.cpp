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

namespace {

/// Mean |B| per region and, when `da` is given, its derivative along da.
MeanBSlope mean_b(const magnetostatics::MagnetostaticSolver& statics,
                  const std::vector<int>& regions, const Eigen::VectorXd& a,
                  const Eigen::VectorXd* da, const Eigen::VectorXd* zero_direction) {
  const mesh::Mesh& m = statics.mesh();
  std::vector<int> slot(statics.problem().regions.size(), -1);
  for (std::size_t k = 0; k < regions.size(); ++k) slot[regions[k]] = static_cast<int>(k);
  MeanBSlope out{std::vector<double>(regions.size(), 0.0),
                 std::vector<double>(regions.size(), 0.0)};
  std::vector<double> area(regions.size(), 0.0);
  magnetostatics::ElementQuadrature q;
  double a_local[magnetostatics::kMaxElementNodes], da_local[magnetostatics::kMaxElementNodes];
  double zero_local[magnetostatics::kMaxElementNodes];
  for (int e = 0; e < static_cast<int>(m.triangles.size()); ++e) {
    const int k = slot[m.region[e]];
    if (k < 0) continue;
    statics.assembler().quadrature(e, q);
    for (int i = 0; i < q.nodes; ++i) {
      a_local[i] = a[m.triangles[e][i]];
      if (da) da_local[i] = (*da)[m.triangles[e][i]];
      if (zero_direction) zero_local[i] = (*zero_direction)[m.triangles[e][i]];
    }
    for (int p = 0; p < q.points; ++p) {
      const auto b = magnetostatics::element_b(q, p, a_local);
      const double magnitude = std::hypot(b[0], b[1]);
      out.b[k] += q.area_weight[p] * magnitude;
      area[k] += q.area_weight[p];
      if (!da) continue;
      // Where B = 0, |B| grows along the direction B takes next (zero_direction's field).
      const auto direction =
          magnitude > 0.0 || !zero_direction ? b : magnetostatics::element_b(q, p, zero_local);
      const double length = std::hypot(direction[0], direction[1]);
      if (length > 0.0) {
        const auto db = magnetostatics::element_b(q, p, da_local);
        out.slope[k] += q.area_weight[p] * (direction[0] * db[0] + direction[1] * db[1]) / length;
      }
    }
  }
  for (std::size_t k = 0; k < regions.size(); ++k) {
    out.b[k] = area[k] > 0.0 ? out.b[k] / area[k] : 0.0;
    out.slope[k] = area[k] > 0.0 ? out.slope[k] / area[k] : 0.0;
  }
  return out;
}

}  // namespace

std::vector<double> region_mean_b(const magnetostatics::MagnetostaticSolver& statics,
                                  const std::vector<int>& regions, const Eigen::VectorXd& a) {
  return mean_b(statics, regions, a, nullptr, nullptr).b;
}

MeanBSlope region_mean_b_slope(const magnetostatics::MagnetostaticSolver& statics,
                               const std::vector<int>& regions, const Eigen::VectorXd& a,
                               const Eigen::VectorXd& da, const Eigen::VectorXd& zero_direction) {
  return mean_b(statics, regions, a, &da, &zero_direction);
}

}  // namespace rheomag::transient
