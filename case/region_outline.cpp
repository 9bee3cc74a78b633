// Arc discretisation for region outlines and FEMM arc segments.

#include "case/region_outline.hpp"

#include <cmath>
#include <numbers>

namespace rheomag::cases {

void append_arc(std::vector<mesh::Point>& out, mesh::Point from, mesh::Point to, double degrees,
                double max_segment_degrees) {
  const double dr = to.r - from.r;
  const double dz = to.z - from.z;
  const double chord = std::hypot(dr, dz);
  const double theta = degrees * std::numbers::pi / 180.0;
  const double half = 0.5 * std::abs(theta);
  const int pieces =
      std::max(1, static_cast<int>(std::ceil(std::abs(degrees) / max_segment_degrees - 1e-9)));
  if (chord == 0.0 || half <= 0.0 || pieces == 1) {
    out.push_back(to);
    return;
  }
  // Centre: on the chord's perpendicular bisector, left of from->to for a counter-clockwise arc
  // shorter than a half circle (cos(half) changes sign beyond 180 degrees).
  const double radius = chord / (2.0 * std::sin(half));
  const double side = theta > 0.0 ? 1.0 : -1.0;
  const double offset = side * radius * std::cos(half);
  const mesh::Point centre{0.5 * (from.r + to.r) - offset * dz / chord,
                           0.5 * (from.z + to.z) + offset * dr / chord};
  const double start = std::atan2(from.z - centre.z, from.r - centre.r);
  for (int k = 1; k < pieces; ++k) {
    const double angle = start + theta * static_cast<double>(k) / pieces;
    out.push_back({centre.r + radius * std::cos(angle), centre.z + radius * std::sin(angle)});
  }
  out.push_back(to);
}

}  // namespace rheomag::cases
