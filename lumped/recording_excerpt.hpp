#pragma once
// A part of a recording: the same columns and sidecar over a range of samples.

#include "lumped/metrics.hpp"
#include "lumped/recording.hpp"

namespace rheomag::lumped {

/// The samples `range` of `rec` (every column, times unchanged, the same sidecar).
Recording excerpt(const Recording& rec, SampleRange range);

}  // namespace rheomag::lumped
