// The noise-robust path of a measured current (reversals beyond the noise, monotone between).

#include "diagnose/current_path.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace rheomag::diagnose {

namespace {

/// Turning points of `x`: the extremes after which it swings back by more than `band` (a
/// zigzag). `rising` is the direction of the first run (from sample 0 to the first turn);
/// `swings` is false when `x` never moves by more than `band` at all.
struct Turns {
  std::vector<std::size_t> at;
  bool rising = true;
  bool swings = false;
};

Turns turning_points(const std::vector<double>& x, double band) {
  Turns out;
  std::size_t lo = 0, hi = 0, k = 0;
  for (; k < x.size(); ++k) {  // until the first swing beyond the band
    if (x[k] > x[hi]) hi = k;
    if (x[k] < x[lo]) lo = k;
    if (x[k] - x[lo] > band || x[hi] - x[k] > band) break;
  }
  if (k == x.size()) return out;
  out.swings = true;
  out.rising = x[k] - x[lo] > band;
  bool rising = out.rising;
  std::size_t extreme = k;
  for (++k; k < x.size(); ++k) {
    const double s = rising ? 1.0 : -1.0;
    if (s * (x[k] - x[extreme]) >= 0.0) {
      extreme = k;
    } else if (s * (x[extreme] - x[k]) > band) {
      out.at.push_back(extreme);
      rising = !rising;
      extreme = k;
    }
  }
  return out;
}

/// Least-squares non-decreasing (or non-increasing) fit of x[first, last) written into `out`
/// (pool-adjacent-violators).
void monotone_fit(const std::vector<double>& x, std::size_t first, std::size_t last, bool rising,
                  std::vector<double>& out) {
  struct Block {
    double sum;
    std::size_t count;
  };
  const double s = rising ? 1.0 : -1.0;
  std::vector<Block> blocks;
  for (std::size_t k = first; k < last; ++k) {
    blocks.push_back({s * x[k], 1});
    while (blocks.size() > 1) {
      const Block& b = blocks.back();
      const Block& a = blocks[blocks.size() - 2];
      if (a.sum * static_cast<double>(b.count) <= b.sum * static_cast<double>(a.count)) break;
      const Block merged{a.sum + b.sum, a.count + b.count};
      blocks.pop_back();
      blocks.back() = merged;
    }
  }
  std::size_t k = first;
  for (const Block& b : blocks)
    for (std::size_t j = 0; j < b.count; ++j) out[k++] = s * b.sum / static_cast<double>(b.count);
}

}  // namespace

double reversal_band(double sigma, std::size_t samples) {
  const double n = static_cast<double>(std::max<std::size_t>(samples, 2));
  return 2.0 * sigma * std::sqrt(2.0 * std::log(n));
}

std::vector<double> current_path(const std::vector<double>& x, double band) {
  if (!(band > 0.0) || x.size() < 3) return x;
  const std::size_t n = x.size();
  const Turns turns = turning_points(x, band);
  if (!turns.swings)
    return std::vector<double>(n, std::accumulate(x.begin(), x.end(), 0.0) / double(n));
  // Plateaus: the contiguous samples within the band of each turning extreme, kept between the
  // midpoints to the neighbouring turns (so two plateaus never overlap); each is its mean.
  const std::size_t m = turns.at.size();
  std::vector<std::size_t> begin(m), end(m);  // [begin, end)
  std::vector<double> level(m);
  std::vector<double> out(n);
  bool maximum = turns.rising;  // the first turn ends the first run
  for (std::size_t j = 0; j < m; ++j, maximum = !maximum) {
    const std::size_t t = turns.at[j];
    const std::size_t left = j == 0 ? 0 : (turns.at[j - 1] + t) / 2 + 1;
    const std::size_t right = j + 1 == m ? n : (t + turns.at[j + 1]) / 2 + 1;
    auto inside = [&](std::size_t k) {
      return maximum ? x[k] >= x[t] - band : x[k] <= x[t] + band;
    };
    std::size_t a = t, b = t + 1;
    while (a > left && inside(a - 1)) --a;
    while (b < right && inside(b)) ++b;
    begin[j] = a;
    end[j] = b;
    level[j] = std::accumulate(x.begin() + a, x.begin() + b, 0.0) / static_cast<double>(b - a);
    std::fill(out.begin() + a, out.begin() + b, level[j]);
  }
  // Runs between the plateaus: monotone fits, bounded by the levels at their ends.
  bool rising = turns.rising;
  for (std::size_t j = 0; j <= m; ++j, rising = !rising) {
    const std::size_t first = j == 0 ? 0 : end[j - 1];
    const std::size_t last = j == m ? n : begin[j];
    if (first >= last) continue;
    monotone_fit(x, first, last, rising, out);
    double lo = -HUGE_VAL, hi = HUGE_VAL;
    for (std::size_t e : {j, j + 1}) {
      if (e == 0 || e > m) continue;
      const double v = level[e - 1];
      // The plateau before a rising run is a minimum, the one after it a maximum.
      const bool is_max = (e == j) != rising;
      if (is_max)
        hi = std::min(hi, v);
      else
        lo = std::max(lo, v);
    }
    for (std::size_t k = first; k < last; ++k) out[k] = std::clamp(out[k], std::min(lo, hi), hi);
  }
  return out;
}

}  // namespace rheomag::diagnose
