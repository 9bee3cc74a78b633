#pragma once
// How far a recording repeats itself under a periodic drive: the FIT of its own mean cycle on its
// steady cycles. A model whose output answers a periodic drive with a periodic output cannot beat
// this on those cycles, so it tells a user how much of a model's error is the test's own
// cycle-to-cycle scatter (drift, noise) rather than missing physics.

#include <cstddef>
#include <optional>
#include <vector>

namespace rheomag::identify {

/// One cycle of a periodic drive: samples [begin, end) between two upward crossings at times
/// start and stop.
struct DriveCycle {
  std::size_t begin = 0, end = 0;
  double start = 0.0, stop = 0.0;
};

/// The steady cycles of the drive v(t), in time order: the cycles between its upward crossings
/// (lumped::upward_crossings) whose swings (max - min of v) lie in one 2 % band, the band that
/// holds the most cycles (ties: the larger swings). A start-up ramp and a start-up overshoot (a
/// shaking table's first cycle a few % larger) are left out. Empty for a drive that is not
/// periodic (lumped::drive_period) or with fewer than two crossings.
std::vector<DriveCycle> steady_cycles(const std::vector<double>& t, const std::vector<double>& v);

/// FIT % (100 (1 - ||y - y_cycle|| / ||y - mean y||)) of the mean cycle y_cycle on the steady
/// cycles of y(t) under the drive v(t): cycles between v's upward crossings (upward_crossings)
/// whose drive swings lie within one 2 % band, the band that holds the most cycles (ties: the
/// larger swings); each sample is compared with the other steady
/// cycles' mean at its phase (linear interpolation), the squared error scaled by (n-1)/(n-1+2/3)
/// for the noise that mean carries over n cycles (at most 64 cycles, evenly spread, are used).
/// Empty without at least 3 steady cycles, for a
/// drive that is not periodic (drive_period) or repeats itself to less than 95 % by the same
/// measure.
std::optional<double> repeatability_percent(const std::vector<double>& t,
                                            const std::vector<double>& v,
                                            const std::vector<double>& y);

}  // namespace rheomag::identify
