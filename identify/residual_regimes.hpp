#pragma once
// Where in a damper's cycle a prediction misses: its residual split by regime of the measured
// cycle, so a user sees whether a model is short at the reversals (pre-yield, compliance, seal
// presliding: the part of each stroke a small stroke is mostly made of) or in the strokes
// themselves, and whether it misses one direction of motion more than the other (an asymmetric
// valve or accumulator).

#include <optional>
#include <vector>

namespace rheomag::identify {

/// The residual (prediction minus measurement) on the samples of one regime.
struct RegimeResidual {
  double time_percent = 0.0;    ///< the regime's share of the samples
  double energy_percent = 0.0;  ///< its share of the residual's sum of squares
  double rms = 0.0;             ///< [output unit] rms of the residual on the regime (0 if empty)
  double mean = 0.0;            ///< [output unit] mean of the residual on it: a bias (0 if empty)
};

/// The residual of a prediction by regime of the measured cycle. A stroke is a run of samples
/// with one direction of motion (a reversal needs the motion to cross a band of
/// kReversalBandFraction of its rms, so noise does not split a stroke). Its `transition` is from
/// the reversal until the measured force (about its mean over the recording, so an offset does not
/// count as a direction), taken in the direction it opposes the motion, first
/// reaches kSettledFraction of its median over the stroke: the pre-yield, compliance and
/// low-speed part. The rest of the stroke is `positive` or `negative` by the motion's sign.
struct ResidualRegimes {
  RegimeResidual transition;  ///< after each reversal, until the force has settled
  RegimeResidual positive;    ///< settled, motion > 0
  RegimeResidual negative;    ///< settled, motion < 0
};

/// A reversal: the motion crosses +- this fraction of its rms.
inline constexpr double kReversalBandFraction = 0.05;
/// The force has settled at this fraction of its median over the stroke.
inline constexpr double kSettledFraction = 0.9;

/// The regimes of `prediction` against the measured output `measured` under the drive `motion`
/// (velocity or flow; equal lengths). Empty if the lengths differ, there are fewer than 2 samples
/// or the motion is constant.
std::optional<ResidualRegimes> residual_regimes(const std::vector<double>& motion,
                                                const std::vector<double>& measured,
                                                const std::vector<double>& prediction);

}  // namespace rheomag::identify
