#include "magnetostatics/bh_curve.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "case/femm_bh_smoothing.hpp"
#include "core/constants.hpp"
#include "core/error.hpp"

namespace rheomag::magnetostatics {
namespace {

[[noreturn]] void fail(const std::string& material, const std::string& what) {
  throw InputError("material '" + material + "': B-H table " + what);
}

}  // namespace

BhCurve::BhCurve(const std::vector<cases::BhPoint>& table, const std::string& material,
                 cases::BhInterpolation interpolation) {
  if (table.size() < 2) {
    fail(material, "has " + std::to_string(table.size()) + " point(s); expected at least 2");
  }
  for (std::size_t k = 0; k < table.size(); ++k) {
    const cases::BhPoint& p = table[k];
    if (!std::isfinite(p.b) || !std::isfinite(p.h) || p.b < 0.0 || p.h < 0.0) {
      std::ostringstream msg;
      msg << "point " << k + 1 << " (B = " << p.b << " T, H = " << p.h
          << " A/m) is not a finite non-negative number pair";
      fail(material, msg.str());
    }
    if (k > 0 && !(p.b > table[k - 1].b && p.h > table[k - 1].h)) {
      std::ostringstream msg;
      msg << "is not strictly increasing at point " << k + 1 << " (B = " << p.b << " T, H = " << p.h
          << " A/m after B = " << table[k - 1].b << " T, H = " << table[k - 1].h << " A/m)";
      fail(material, msg.str());
    }
  }
  if (table.front().b != 0.0 || table.front().h != 0.0) {
    if (table.front().b == 0.0 || table.front().h == 0.0) {
      fail(material, "must start at (0, 0) or at a point with B > 0 and H > 0");
    }
    b_.push_back(0.0);
    h_.push_back(0.0);
  }
  for (const cases::BhPoint& p : table) {
    b_.push_back(p.b);
    h_.push_back(p.h);
  }

  // Slopes d_k at the table points (Fritsch-Carlson monotone: PCHIP weighted harmonic mean).
  const std::size_t n = b_.size() - 1;  // number of intervals
  std::vector<double> width(n), secant(n), slope(n + 1, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    width[k] = b_[k + 1] - b_[k];
    secant[k] = (h_[k + 1] - h_[k]) / width[k];
  }
  for (std::size_t k = 1; k < n; ++k) {
    const double w1 = 2.0 * width[k] + width[k - 1];
    const double w2 = width[k] + 2.0 * width[k - 1];
    slope[k] = (w1 + w2) / (w1 / secant[k - 1] + w2 / secant[k]);
  }
  if (n == 1) {
    slope[1] = secant[0];
  } else {
    // One-sided three-point end slope, kept in [0.5, 3] x the last secant: inside the
    // Fritsch-Carlson monotonicity box and strictly positive.
    const double end =
        ((2.0 * width[n - 1] + width[n - 2]) * secant[n - 1] - width[n - 1] * secant[n - 2]) /
        (width[n - 1] + width[n - 2]);
    slope[n] = std::clamp(end, 0.5 * secant[n - 1], 3.0 * secant[n - 1]);
  }
  // First interval H = B (a + c B^2): a = (3 s0 - d1) / 2 > 0 needs d1 < 3 s0.
  slope[1] = std::min(slope[1], 2.5 * secant[0]);
  if (interpolation == cases::BhInterpolation::femm_natural_spline) {
    // FEMM's natural spline: 2 d0 + d1 = 3 s0 on the first interval, so its cubic is the odd
    // polynomial with a = d0.
    std::vector<std::pair<double, double>> points;
    for (std::size_t k = 0; k <= n; ++k) points.emplace_back(b_[k], h_[k]);
    const std::vector<double> femm = cases::femm_spline_slopes(points);
    const bool positive =
        femm.size() == n + 1 &&
        std::all_of(femm.begin(), femm.end(), [](double d) { return std::isfinite(d) && d > 0.0; });
    if (positive && !cases::femm_spline_turns_back(points)) slope.assign(femm.begin(), femm.end());
  }
  a_ = 0.5 * (3.0 * secant[0] - slope[1]);
  c_ = (slope[1] - secant[0]) / (2.0 * b_[1] * b_[1]);

  end_slope_ = slope[n];
  tau_ = width[n - 1];
  for (std::size_t k = 1; k < n; ++k) {
    cubics_.push_back(hermite(b_[k], b_[k + 1], h_[k], h_[k + 1], slope[k], slope[k + 1]));
  }
  const int cells = 4 * static_cast<int>(n);
  cell_scale_ = cells / (b_.back() - b_[1]);
  for (int c = 0; c < cells; ++c) {
    const double left = b_[1] + c / cell_scale_;
    cell_first_.push_back(
        static_cast<int>(std::lower_bound(b_.begin() + 1, b_.end(), left) - b_.begin()));
  }
  energy_at_.assign(n + 1, 0.0);
  energy_at_[1] = 0.5 * a_ * b_[1] * b_[1] + 0.25 * c_ * std::pow(b_[1], 4);
  for (std::size_t k = 1; k < n; ++k) {
    energy_at_[k + 1] = energy_at_[k] + cubic_energy(cubics_[k - 1], b_[k + 1]);
  }
}

int BhCurve::interval(double b) const {
  if (b <= b_[1]) return -1;
  if (b > b_.back()) return static_cast<int>(cubics_.size());
  // The first k with b_[k] >= b (k >= 2), as std::lower_bound, from the cell's start: the two
  // steps make it exact whatever the rounding of the cell index.
  const int cells = static_cast<int>(cell_first_.size());
  const int cell = std::clamp(static_cast<int>((b - b_[1]) * cell_scale_), 0, cells - 1);
  int k = cell_first_[cell];
  while (k > 1 && b_[k - 1] >= b) --k;
  while (b_[k] < b) ++k;
  return k - 2;
}

BhCurve::Cubic BhCurve::hermite(double b0, double b1, double h0, double h1, double d0, double d1) {
  const double w = b1 - b0;
  return {b0,
          w,
          1.0 / w,
          h0,
          w * d0,
          3.0 * (h1 - h0) - w * (2.0 * d0 + d1),
          2.0 * (h0 - h1) + w * (d0 + d1)};
}

double BhCurve::cubic_h(const Cubic& c, double b) const {
  const double t = (b - c.b0) * c.inv_w;
  return c.p0 + t * (c.p1 + t * (c.p2 + t * c.p3));
}

double BhCurve::cubic_dh(const Cubic& c, double b) const {
  const double t = (b - c.b0) * c.inv_w;
  return (c.p1 + t * (2.0 * c.p2 + t * 3.0 * c.p3)) * c.inv_w;
}

double BhCurve::cubic_energy(const Cubic& c, double b) const {
  const double t = (b - c.b0) * c.inv_w;
  return c.w * t * (c.p0 + t * (0.5 * c.p1 + t * (c.p2 / 3.0 + t * 0.25 * c.p3)));
}

double BhCurve::h(double b) const {
  const int k = interval(b);
  if (k < 0) return b * (a_ + c_ * b * b);
  if (k == static_cast<int>(cubics_.size())) {
    const double x = b - b_.back();
    return h_.back() + kNu0 * x - (end_slope_ - kNu0) * tau_ * std::expm1(-x / tau_);
  }
  return cubic_h(cubics_[k], b);
}

double BhCurve::dh_db(double b) const {
  const int k = interval(b);
  if (k < 0) return a_ + 3.0 * c_ * b * b;
  if (k == static_cast<int>(cubics_.size())) {
    return kNu0 + (end_slope_ - kNu0) * std::exp(-(b - b_.back()) / tau_);
  }
  return cubic_dh(cubics_[k], b);
}

double BhCurve::nu(double b2) const {
  const double b = std::sqrt(b2);
  if (b <= b_[1]) return a_ + c_ * b2;
  return h(b) / b;
}

double BhCurve::dnu_db2(double b2) const {
  const double b = std::sqrt(b2);
  if (b <= b_[1]) return c_;
  return (dh_db(b) - h(b) / b) / (2.0 * b2);
}

std::pair<double, double> BhCurve::nu_and_dnu_db2(double b2) const {
  const double b = std::sqrt(b2);
  if (b <= b_[1]) return {a_ + c_ * b2, c_};
  const int k = interval(b);
  double h = 0.0, dh = 0.0;
  if (k < 0) {
    h = b * (a_ + c_ * b * b);
    dh = a_ + 3.0 * c_ * b * b;
  } else if (k == static_cast<int>(cubics_.size())) {
    const double x = b - b_.back();
    h = h_.back() + kNu0 * x - (end_slope_ - kNu0) * tau_ * std::expm1(-x / tau_);
    dh = kNu0 + (end_slope_ - kNu0) * std::exp(-x / tau_);
  } else {
    h = cubic_h(cubics_[k], b);
    dh = cubic_dh(cubics_[k], b);
  }
  return {h / b, (dh - h / b) / (2.0 * b2)};
}

double BhCurve::energy_density(double b) const {
  const int k = interval(b);
  if (k < 0) return 0.5 * a_ * b * b + 0.25 * c_ * b * b * b * b;
  if (k == static_cast<int>(cubics_.size())) {
    const double x = b - b_.back();
    return energy_at_.back() + h_.back() * x + 0.5 * kNu0 * x * x +
           (end_slope_ - kNu0) * tau_ * (x + tau_ * std::expm1(-x / tau_));
  }
  return energy_at_[k + 1] + cubic_energy(cubics_[k], b);
}

}  // namespace rheomag::magnetostatics
