#include "magnetostatics3d/band_coil.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "magnetostatics3d/coil_source.hpp"

namespace rheomag::magnetostatics3d {

double band_coil_depth(const BandCoil& coil, double x, double y) {
  // Signed distance of a rounded rectangle: the core rectangle grown by the corner radius.
  const double qx = std::abs(x) - (coil.half_x - coil.corner_radius);
  const double qy = std::abs(y) - (coil.half_y - coil.corner_radius);
  const double outside = std::hypot(std::max(qx, 0.0), std::max(qy, 0.0));
  const double inside = std::min(std::max(qx, qy), 0.0);
  return coil.corner_radius - outside - inside;
}

double band_coil_tz(const BandCoil& coil, const Eigen::Vector3d& p) {
  if (p[2] < coil.z0 || p[2] > coil.z1) return 0.0;
  const double depth = std::clamp(band_coil_depth(coil, p[0], p[1]), 0.0, coil.width);
  return coil.turns / (coil.width * (coil.z1 - coil.z0)) * depth;
}

Eigen::VectorXd band_coil_loads(const BandCoil& coil, const TetMesh& mesh) {
  const double smaller = std::min(coil.half_x, coil.half_y);
  if (!(coil.corner_radius >= 0 && coil.corner_radius <= smaller && coil.width > 0 &&
        coil.width < smaller && coil.z1 > coil.z0 && std::isfinite(coil.turns))) {
    throw InputError(
        "band coil: need 0 <= corner radius <= half sizes, 0 < width < half sizes, "
        "z1 > z0 and finite turns");
  }
  const auto jumps = [&](double lo, double hi) {
    return (coil.z0 > lo && coil.z0 < hi) || (coil.z1 > lo && coil.z1 < hi);
  };
  const auto tz = [&](const Eigen::Vector3d& p) { return band_coil_tz(coil, p); };
  return z_source_loads(mesh, mesh.nodes, tz, coil.z0, coil.z1, jumps);
}

}  // namespace rheomag::magnetostatics3d
