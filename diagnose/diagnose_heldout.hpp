#pragma once
// The two-fold held-out check of a candidate: fit on alternate time blocks, score on the others.

#include <vector>

#include "diagnose/diagnose_fit.hpp"

namespace rheomag::diagnose {

/// Mask of the samples in the even (`even`) or odd of `blocks` equal time blocks of `n` samples.
std::vector<bool> block_mask(std::size_t n, int blocks, bool even);

/// Held-out squared error: fit on even blocks, score on odd, and the other way round (the two
/// folds on two threads when `threads` > 1); only on the samples of `keep` when it is not empty
/// (the samples away from steps: a fold fitted to the steps' residual moves the delay and the
/// candidate with the few steps the fold holds).
double heldout_sse(const DiagnosisModel& model, const ModelFit& full, int blocks, int iterations,
                   int threads, const std::vector<bool>& keep);

}  // namespace rheomag::diagnose
