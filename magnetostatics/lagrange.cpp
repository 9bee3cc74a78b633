#include "magnetostatics/lagrange.hpp"

#include <cmath>

namespace rheomag::magnetostatics {
namespace {

std::vector<TriangleQuadraturePoint> symmetric_rule(
    const std::vector<std::pair<double, double>>& orbits, double centroid_weight) {
  // Each orbit (a, w): the three points with barycentric coordinates (a, a, 1 - 2a).
  std::vector<TriangleQuadraturePoint> rule;
  if (centroid_weight > 0.0) rule.push_back({1.0 / 3.0, 1.0 / 3.0, centroid_weight});
  for (const auto& [a, w] : orbits) {
    const double b = 1.0 - 2.0 * a;
    rule.push_back({a, a, w});
    rule.push_back({a, b, w});
    rule.push_back({b, a, w});
  }
  return rule;
}

}  // namespace

const std::vector<TriangleQuadraturePoint>& triangle_quadrature(int order) {
  static const std::vector<TriangleQuadraturePoint> degree4 = symmetric_rule(
      {{0.445948490915965, 0.223381589678011}, {0.091576213509771, 0.109951743655322}}, 0.0);
  static const std::vector<TriangleQuadraturePoint> degree5 = [] {
    const double s = std::sqrt(15.0);
    return symmetric_rule(
        {{(6.0 - s) / 21.0, (155.0 - s) / 1200.0}, {(6.0 + s) / 21.0, (155.0 + s) / 1200.0}},
        9.0 / 40.0);
  }();
  return order == 1 ? degree4 : degree5;
}

void lagrange_basis(int order, double xi, double eta, double* value, double* d_xi, double* d_eta) {
  const double l0 = 1.0 - xi - eta, l1 = xi, l2 = eta;
  if (order == 1) {
    value[0] = l0, value[1] = l1, value[2] = l2;
    d_xi[0] = -1.0, d_xi[1] = 1.0, d_xi[2] = 0.0;
    d_eta[0] = -1.0, d_eta[1] = 0.0, d_eta[2] = 1.0;
    return;
  }
  value[0] = l0 * (2.0 * l0 - 1.0);
  value[1] = l1 * (2.0 * l1 - 1.0);
  value[2] = l2 * (2.0 * l2 - 1.0);
  value[3] = 4.0 * l0 * l1;
  value[4] = 4.0 * l1 * l2;
  value[5] = 4.0 * l2 * l0;
  d_xi[0] = 1.0 - 4.0 * l0;
  d_xi[1] = 4.0 * l1 - 1.0;
  d_xi[2] = 0.0;
  d_xi[3] = 4.0 * (l0 - l1);
  d_xi[4] = 4.0 * l2;
  d_xi[5] = -4.0 * l2;
  d_eta[0] = 1.0 - 4.0 * l0;
  d_eta[1] = 0.0;
  d_eta[2] = 4.0 * l2 - 1.0;
  d_eta[3] = -4.0 * l1;
  d_eta[4] = 4.0 * l1;
  d_eta[5] = 4.0 * (l0 - l2);
}

const std::vector<EdgeQuadraturePoint>& edge_quadrature() {
  static const std::vector<EdgeQuadraturePoint> rule = [] {
    const double x = 0.5 * std::sqrt(0.6);
    return std::vector<EdgeQuadraturePoint>{
        {0.5 - x, 5.0 / 18.0}, {0.5, 8.0 / 18.0}, {0.5 + x, 5.0 / 18.0}};
  }();
  return rule;
}

void edge_basis(int order, double t, double* value) {
  if (order == 1) {
    value[0] = 1.0 - t, value[1] = t;
    return;
  }
  value[0] = (1.0 - t) * (1.0 - 2.0 * t);
  value[1] = t * (2.0 * t - 1.0);
  value[2] = 4.0 * t * (1.0 - t);
}

}  // namespace rheomag::magnetostatics
