// FEMM's smoothing of B-H tables whose spline is not single-valued.

#include "case/femm_bh_smoothing.hpp"

#include <Eigen/SparseCore>
#include <Eigen/SparseLU>
#include <cmath>
#include <cstddef>

namespace rheomag::cases {

namespace {

using Table = std::vector<std::pair<double, double>>;

/// Slopes dH/dB at the points of the natural cubic spline through H(B): continuous second
/// derivative at interior points, zero second derivative at both ends. Empty if singular.
Eigen::VectorXd natural_spline_slopes(const Table& t) {
  const Eigen::Index n = static_cast<Eigen::Index>(t.size());
  std::vector<Eigen::Triplet<double>> entries;
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 0; i + 1 < n; ++i) {
    // Interval i contributes to the equations of its two end points.
    const double l = t[i + 1].first - t[i].first;
    const double rise = 6.0 * (t[i + 1].second - t[i].second) / (l * l);
    entries.emplace_back(i, i, 4.0 / l);
    entries.emplace_back(i, i + 1, 2.0 / l);
    entries.emplace_back(i + 1, i, 2.0 / l);
    entries.emplace_back(i + 1, i + 1, 4.0 / l);
    rhs[i] += rise;
    rhs[i + 1] += rise;
  }
  Eigen::SparseMatrix<double> matrix(n, n);
  matrix.setFromTriplets(entries.begin(), entries.end());
  Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(matrix);
  if (lu.info() != Eigen::Success) return {};
  Eigen::VectorXd slopes = lu.solve(rhs);
  if (lu.info() != Eigen::Success || !slopes.allFinite()) return {};
  return slopes;
}

/// True when the cubic Hermite interpolant on [0, l] with end values h0, h1 and end slopes d0,
/// d1 has dH/dB = 0 somewhere in [0, l] (FEMM's test) or a negative end slope.
bool interval_turns_back(double l, double h0, double h1, double d0, double d1) {
  if (d0 < 0.0 || d1 < 0.0) return true;
  // dH/dB = c0 + c1 x + c2 x^2 for the Hermite cubic.
  const double mean_slope = (h1 - h0) / l;
  const double c0 = d0;
  const double c1 = (6.0 * mean_slope - 4.0 * d0 - 2.0 * d1) / l;
  const double c2 = (3.0 * d0 + 3.0 * d1 - 6.0 * mean_slope) / (l * l);
  auto inside = [l](double x) { return x >= 0.0 && x <= l; };
  if (c2 == 0.0) return c1 != 0.0 && inside(-c0 / c1);
  const double discriminant = c1 * c1 - 4.0 * c0 * c2;
  if (discriminant <= 0.0) return false;
  const double root = std::sqrt(discriminant);
  return inside(-(c1 + root) / (2.0 * c2)) || inside((root - c1) / (2.0 * c2));
}

/// One pass of FEMM's remedy: every interior point becomes the mean of itself and its two
/// neighbours (all from the previous pass); the end points stay.
void average_interior_points(Table& t) {
  const Table previous = t;
  for (std::size_t i = 1; i + 1 < t.size(); ++i) {
    t[i].first = (previous[i - 1].first + previous[i].first + previous[i + 1].first) / 3.0;
    t[i].second = (previous[i - 1].second + previous[i].second + previous[i + 1].second) / 3.0;
  }
}

}  // namespace

std::vector<double> femm_spline_slopes(const Table& points) {
  if (points.size() < 2) return {};
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    if (!(points[i + 1].first > points[i].first)) return {};
  const Eigen::VectorXd slopes = natural_spline_slopes(points);
  return std::vector<double>(slopes.begin(), slopes.end());
}

bool femm_spline_turns_back(const Table& points) {
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    if (!(points[i + 1].first > points[i].first)) return true;
  if (points.size() < 2) return false;
  const Eigen::VectorXd slopes = natural_spline_slopes(points);
  if (slopes.size() == 0) return true;
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const auto k = static_cast<Eigen::Index>(i);
    if (interval_turns_back(points[i + 1].first - points[i].first, points[i].second,
                            points[i + 1].second, slopes[k], slopes[k + 1]))
      return true;
  }
  return false;
}

FemmSmoothedTable femm_smoothed_bh_table(Table points, int max_passes) {
  FemmSmoothedTable result;
  if (points.size() < 3) {
    result.points = std::move(points);
    return result;
  }
  while (result.passes < max_passes && femm_spline_turns_back(points)) {
    average_interior_points(points);
    ++result.passes;
  }
  result.points = std::move(points);
  return result;
}

}  // namespace rheomag::cases
