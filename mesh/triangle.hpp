#pragma once
// Area and centroid of one triangle of the meridian plane, written once for every library.

#include <cmath>

#include "mesh/pslg.hpp"

namespace rheomag::mesh {

/// Signed area of the triangle (a, b, c) [m^2]: positive when a, b, c turn counter-clockwise.
inline double signed_triangle_area(const Point& a, const Point& b, const Point& c) {
  return 0.5 * ((b.r - a.r) * (c.z - a.z) - (c.r - a.r) * (b.z - a.z));
}

/// Area of the triangle (a, b, c) [m^2] (0.5 |x| is |0.5 x| bit for bit).
inline double triangle_area(const Point& a, const Point& b, const Point& c) {
  return std::abs(signed_triangle_area(a, b, c));
}

/// Centroid of the triangle (a, b, c).
inline Point triangle_centroid(const Point& a, const Point& b, const Point& c) {
  return {(a.r + b.r + c.r) / 3.0, (a.z + b.z + c.z) / 3.0};
}

}  // namespace rheomag::mesh
