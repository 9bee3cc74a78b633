#pragma once
// Acquisition glitches in a measured motion: single samples that leave the path of both their
// neighbours and return (a dropped or corrupted sample). A displacement, velocity or flow cannot
// do that physically, and a model that reads the motion's slope (an inertia's acceleration)
// turns one such sample into a force spike of thousands of times its size.

#include <cstddef>
#include <string>
#include <vector>

namespace rheomag::lumped {

struct Recording;

/// A single sample is a glitch when it is off the mean of its two neighbours by more than this
/// many robust standard deviations of that difference over the whole column ...
inline constexpr double kGlitchDeviations = 12.0;
/// ... and by more than this fraction of the column's spread (1st to 99th percentile), so that a
/// quantised or nearly noise-free column's last-digit flicker, or a coarse velocity's jerk, is
/// never one ...
inline constexpr double kGlitchSpreadFraction = 0.05;
/// ... while its two neighbours agree (they differ by less than half its departure: a step's
/// edge is not a glitch). More glitches than this fraction of the samples are the signal's own
/// structure at the sample rate (a dither, a chatter), not glitches: none are reported.
inline constexpr double kGlitchMaxFraction = 0.005;

/// The glitches of one column.
struct MotionGlitches {
  std::vector<std::size_t> samples;  ///< indices of the glitched samples, ascending
  double largest = 0.0;              ///< largest departure from the neighbours' mean (SI)
};

/// True for the columns that are a measured motion (displacement, velocity, flow).
bool is_motion_column(const std::string& column);

/// The isolated single-sample glitches of `u` sampled at `t` (see the constants above); the
/// first and last samples are compared with the straight line through their next two. With the
/// recording's `displacement` given for a velocity `u`, a sample that the displacement's
/// backward, forward or central difference follows to within half its departure is motion that
/// happened (a table's jerk), not a glitch.
MotionGlitches find_motion_glitches(const std::vector<double>& u, const std::vector<double>& t,
                                    const std::vector<double>* displacement = nullptr);

/// The glitches of `rec`'s column `column`: a motion's (a velocity checked against the
/// recording's displacement where it has one), none for any other column.
MotionGlitches find_motion_glitches(const Recording& rec, const std::string& column);

/// `rec`'s column `column` as a model reads it: a motion's glitches replaced by its neighbours'
/// path (without_glitches), any other column as recorded.
std::vector<double> column_without_glitches(const Recording& rec, const std::string& column);

/// `u` with each glitched sample replaced by the mean of its neighbours (at an end: the straight
/// line through its next two).
std::vector<double> without_glitches(std::vector<double> u, const MotionGlitches& glitches);

/// One line naming a column's glitches: how many, the first's time and sample, the largest.
std::string describe_glitches(const std::string& column, const MotionGlitches& glitches,
                              const std::vector<double>& t);

}  // namespace rheomag::lumped
