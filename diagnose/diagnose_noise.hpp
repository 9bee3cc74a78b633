#pragma once
// The noise floor of a recording: the standard deviation of the white part of a signal (sensor
// noise, and drive noise that a static map passes straight through), estimated from its
// third differences, which cancel any smooth signal and leave the noise.

#include <cstddef>
#include <vector>

namespace rheomag::diagnose {

/// Standard deviation of the white noise in `x` (robust): 1.4826 MAD(D3 x) / sqrt(20), with D3
/// the third difference x[k+3] - 3 x[k+2] + 3 x[k+1] - x[k] (variance 20 sigma^2 for white
/// noise; a polynomial of degree <= 2 vanishes, the median ignores the few samples at edges).
double noise_sigma(const std::vector<double>& x);

/// Intervals j (between samples j and j + 1) across which `u` steps: it moves by more than 5 %
/// of its range and more than ten times its median move per interval (a step, not noise).
std::vector<std::size_t> step_intervals(const std::vector<double>& u);

/// The samples that carry evidence beyond the recorder's timing (true): all but those within
/// one sample interval of a step of `prediction` (samples j - 1 to j + 2 of each step interval
/// j). A step between two samples happens at an instant the recording does not keep (channel
/// skew, a held or smooth drive); a sample beside it is off by a share of the whole step that
/// no model of the recorded drives can predict. Empty (every sample) when nothing steps.
std::vector<bool> away_from_steps(const std::vector<double>& prediction);

/// A noisy drive smoothed for the model: a cubic Savitzky-Golay filter (centred least-squares
/// cubic over 2 half_width + 1 samples, zero phase; the first and last half_width samples are
/// left as measured). A cubic passes any signal that is locally a cubic unchanged.
struct SmoothedDrive {
  std::vector<double> values;
  double bandwidth = 0.0;  ///< [Hz] -3 dB frequency of the filter at the median sample rate
};

/// Smooths `x` sampled every `dt` seconds (see SmoothedDrive).
SmoothedDrive savitzky_golay(const std::vector<double>& x, double dt, std::size_t half_width);

}  // namespace rheomag::diagnose
