#pragma once
// A banded colour map: a value range cut into equal bins, each drawn in one colour.

#include <array>
#include <vector>

namespace rheomag::plot {

/// An RGB colour, each channel in [0, 1].
struct Rgb {
  double r = 0.0, g = 0.0, b = 0.0;
};

/// Values in [low, high] cut into `bins` equal bins; each bin has one colour of a dark-blue ->
/// blue -> teal -> green -> yellow ramp (increasing lightness). Values outside clamp to the end
/// bins.
class ColourMap {
 public:
  /// [low, high] in `bins` bins (>= 2); std::invalid_argument otherwise.
  ColourMap(double low, double high, int bins);
  /// The bin of `value`, 0 .. bins() - 1.
  int bin(double value) const;
  /// The colour of bin `index`.
  Rgb bin_colour(int index) const { return colours_.at(index); }
  /// The colour of `value` (that of its bin).
  Rgb colour(double value) const { return colours_[bin(value)]; }
  /// The bin whose colour is nearest to `c` (Euclidean in RGB): reads a drawn colour back.
  int nearest_bin(Rgb c) const;
  /// Number of bins.
  int bins() const { return static_cast<int>(colours_.size()); }
  /// Lower end of the range.
  double low() const { return low_; }
  /// Upper end of the range.
  double high() const { return high_; }
  /// Width of one bin.
  double bin_width() const { return (high_ - low_) / bins(); }

 private:
  double low_, high_;
  std::vector<Rgb> colours_;
};

}  // namespace rheomag::plot
