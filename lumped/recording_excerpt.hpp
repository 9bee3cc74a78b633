#pragma once
// A part of a recording: the same columns and sidecar over a range of samples, or every n-th
// sample of a recording too long to fit or diagnose whole.

#include <cstddef>
#include <string>

#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"

namespace rheomag::lumped {

/// The samples `range` of `rec` (every column, times unchanged, the same sidecar).
Recording excerpt(const Recording& rec, SampleRange range);

/// Most samples a fit or a diagnosis works on: 200 000, 2.7 times the longest recording shipped
/// (dyke1996's 74 069 rows). Memory and time grow with the samples (a 10^7-row recording took
/// 6.6 GB and two hours in a grey-box fit); a longer recording is thinned to every n-th sample.
inline constexpr std::size_t kMaxFitSamples = 200000;

/// The n of "every n-th sample" that brings `samples` to at most `max_samples`: ceil(samples /
/// max_samples), 1 when they fit.
std::size_t thinning_factor(std::size_t samples, std::size_t max_samples = kMaxFitSamples);

/// Every `factor`-th sample of `rec` from the first (every column, times unchanged, the same
/// sidecar); `rec` itself when `factor` is 1.
Recording every_nth_sample(const Recording& rec, std::size_t factor);

/// The samples of `range` that every_nth_sample(rec, factor) keeps, as a range of its samples.
SampleRange thinned_range(SampleRange range, std::size_t factor);

/// The stated rule, e.g. "every 50th of its 10000000 samples (rheomag fits and diagnoses at
/// most 200000)", for notes and messages.
std::string thinning_note(std::size_t samples, std::size_t factor);

}  // namespace rheomag::lumped
