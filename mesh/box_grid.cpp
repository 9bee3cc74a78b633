// Counting sort of the boxes into their cells (compressed rows), deduplicated queries.

#include "mesh/box_grid.hpp"

#include <algorithm>
#include <cmath>

namespace rheomag::mesh {
namespace {

/// A box spanning more cells than this is kept aside rather than filed in each.
constexpr long kMaxCellsPerBox = 64;

bool finite(const Box2& b) {
  return std::isfinite(b.r_lo) && std::isfinite(b.r_hi) && std::isfinite(b.z_lo) &&
         std::isfinite(b.z_hi);
}

}  // namespace

BoxGrid::BoxGrid(const std::vector<Box2>& boxes) : boxes_(boxes) {
  double r_lo = HUGE_VAL, r_hi = -HUGE_VAL, z_lo = HUGE_VAL, z_hi = -HUGE_VAL;
  for (const Box2& b : boxes_) {
    if (!finite(b)) continue;
    r_lo = std::min(r_lo, b.r_lo), r_hi = std::max(r_hi, b.r_hi);
    z_lo = std::min(z_lo, b.z_lo), z_hi = std::max(z_hi, b.z_hi);
  }
  const int side = std::clamp(static_cast<int>(std::ceil(std::sqrt(boxes_.size()))), 1, 2048);
  if (r_lo <= r_hi) {
    r0_ = r_lo, z0_ = z_lo;
    columns_ = rows_ = side;
    cell_r_ = r_hi > r_lo ? (r_hi - r_lo) / side : 1.0;
    cell_z_ = z_hi > z_lo ? (z_hi - z_lo) / side : 1.0;
  }
  const auto cells_of = [&](const Box2& b, int& c0, int& c1, int& w0, int& w1) {
    c0 = std::clamp(static_cast<int>(std::floor((b.r_lo - r0_) / cell_r_)), 0, columns_ - 1);
    c1 = std::clamp(static_cast<int>(std::floor((b.r_hi - r0_) / cell_r_)), 0, columns_ - 1);
    w0 = std::clamp(static_cast<int>(std::floor((b.z_lo - z0_) / cell_z_)), 0, rows_ - 1);
    w1 = std::clamp(static_cast<int>(std::floor((b.z_hi - z0_) / cell_z_)), 0, rows_ - 1);
  };
  std::vector<std::size_t> count(static_cast<std::size_t>(columns_) * rows_ + 1, 0);
  std::vector<char> aside(boxes_.size(), 0);
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    int c0, c1, w0, w1;
    if (!finite(boxes_[i]) || (cells_of(boxes_[i], c0, c1, w0, w1),
                               static_cast<long>(c1 - c0 + 1) * (w1 - w0 + 1) > kMaxCellsPerBox)) {
      aside[i] = 1;
      everywhere_.push_back(static_cast<int>(i));
      continue;
    }
    for (int w = w0; w <= w1; ++w)
      for (int c = c0; c <= c1; ++c) ++count[static_cast<std::size_t>(w) * columns_ + c + 1];
  }
  for (std::size_t k = 1; k < count.size(); ++k) count[k] += count[k - 1];
  start_ = count;
  filed_.resize(count.back());
  for (std::size_t i = 0; i < boxes_.size(); ++i) {
    if (aside[i]) continue;
    int c0, c1, w0, w1;
    cells_of(boxes_[i], c0, c1, w0, w1);
    for (int w = w0; w <= w1; ++w)
      for (int c = c0; c <= c1; ++c)
        filed_[count[static_cast<std::size_t>(w) * columns_ + c]++] = static_cast<int>(i);
  }
}

std::vector<int> BoxGrid::candidates(const Box2& query) const {
  std::vector<int> out = everywhere_;
  if (!finite(query)) {
    out.resize(boxes_.size());
    for (std::size_t i = 0; i < out.size(); ++i) out[i] = static_cast<int>(i);
    return out;
  }
  const int c0 =
      std::clamp(static_cast<int>(std::floor((query.r_lo - r0_) / cell_r_)), 0, columns_ - 1);
  const int c1 =
      std::clamp(static_cast<int>(std::floor((query.r_hi - r0_) / cell_r_)), 0, columns_ - 1);
  const int w0 =
      std::clamp(static_cast<int>(std::floor((query.z_lo - z0_) / cell_z_)), 0, rows_ - 1);
  const int w1 =
      std::clamp(static_cast<int>(std::floor((query.z_hi - z0_) / cell_z_)), 0, rows_ - 1);
  for (int w = w0; w <= w1; ++w)
    for (int c = c0; c <= c1; ++c) {
      const std::size_t cell = static_cast<std::size_t>(w) * columns_ + c;
      for (std::size_t k = start_[cell]; k < start_[cell + 1]; ++k) {
        const Box2& b = boxes_[static_cast<std::size_t>(filed_[k])];
        if (b.r_hi < query.r_lo || query.r_hi < b.r_lo || b.z_hi < query.z_lo ||
            query.z_hi < b.z_lo)
          continue;
        out.push_back(filed_[k]);
      }
    }
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

}  // namespace rheomag::mesh
