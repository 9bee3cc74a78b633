#pragma once
// FEMM's remedy for a B-H table whose curve is not single-valued: FEMM fits H(B) with a cubic
// spline and, while any interval's spline turns back (dH/dB changes sign inside it), replaces
// every interior point by the mean of itself and its two neighbours. rheomag applies the same
// remedy to the tables of a .fem file that are not strictly increasing, so that a model FEMM
// solves is solved with the curve FEMM uses.

#include <utility>
#include <vector>

namespace rheomag::cases {

/// A B-H table after FEMM's smoothing and how many passes of it were needed.
struct FemmSmoothedTable {
  std::vector<std::pair<double, double>> points;  ///< (B [T], H [A/m]) as FEMM's solver uses them
  int passes = 0;                                 ///< 0: the table was used as given
};

/// Slopes dH/dB at the points of the natural cubic spline through the table's H(B) (continuous
/// second derivative inside, zero second derivative at both ends: FEMM's CMMaterialProp::
/// GetSlopes at zero frequency). Empty when B does not increase or the system is singular.
std::vector<double> femm_spline_slopes(const std::vector<std::pair<double, double>>& points);

/// True when the cubic spline FEMM fits through the table (H as a function of B, slopes from
/// FEMM's end conditions) has dH/dB = 0 inside some interval, or the table does not increase:
/// the test FEMM repeats after each smoothing pass.
bool femm_spline_turns_back(const std::vector<std::pair<double, double>>& points);

/// Smooths `points` as FEMM does until its spline no longer turns back (at most `max_passes`
/// passes; the end points stay). Tables of fewer than 3 points are returned as given.
FemmSmoothedTable femm_smoothed_bh_table(std::vector<std::pair<double, double>> points,
                                         int max_passes = 10000);

}  // namespace rheomag::cases
