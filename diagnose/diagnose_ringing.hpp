#pragma once
// The hydraulic ringing a compliant baseline leaves in its residual, and the inertance it points
// to: with chamber compliance C in the model, an inertance I makes a lightly damped resonance
// at omega^2 = 1 / (I C), so the error is multimodal in I and a decade grid can miss the right
// one; the ringing frequency measured on the recording gives a start at the right mode.

#include <cstddef>
#include <vector>

#include "diagnose/diagnose_fit.hpp"

namespace rheomag::diagnose {

/// Largest number of ringing frequencies (and inertance starts) taken from one residual.
inline constexpr std::size_t kRingingStarts = 3;

/// Frequencies [Hz] of the strongest resonances in `residual` (sampled every `dt` seconds) above
/// the band of `drive`, strongest first, at most `count`, no two within 25 % of each other.
/// The drive band ends where 99 % of the drive's energy (mean removed) lies below; the search
/// starts at twice that and ends at 0.4 of the sampling rate. Power spectra by Eigen's FFT of
/// the Hann-windowed signals (zero-padded to a power of two); the residual's power is averaged
/// over +-10 % in frequency, so that a resonance excited once per drive cycle (a comb of drive
/// harmonics under its response) shows as one peak, and each peak is placed at the power-
/// weighted mean frequency of its +-10 %. Empty when nothing lies above the band.
std::vector<double> ringing_frequencies(const std::vector<double>& residual,
                                        const std::vector<double>& drive, double dt,
                                        std::size_t count = kRingingStarts);

/// [m^3/Pa] compliance in series with an added inertance in the hydraulic loop of `spec`: the
/// two chambers' in series, C_chamber(precharge) / 2 (0 when the chambers are stiff).
double loop_compliance(const lumped::RigSpec& spec);

/// Start values [Pa s^2/m^3] for the fluid_inertia candidate on top of `current`: I = 1 /
/// (omega^2 C) for each ringing frequency of the residual of `current` (above the velocity's
/// band), with C the loop compliance `current` simulates (the stated oil's, plus any air and
/// pre-yield compliance it includes). Only those within the candidate's `bounds` (its inertance
/// parameter); empty on a coil bench, a fitted-model baseline or stiff chambers.
std::vector<double> ringing_inertances(const DiagnosisModel& model, const ModelFit& current,
                                       const ParamDef& bounds);

}  // namespace rheomag::diagnose
