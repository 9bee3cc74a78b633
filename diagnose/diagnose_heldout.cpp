// The two-fold held-out check of a candidate.

#include "diagnose/diagnose_heldout.hpp"

#include <algorithm>
#include <exception>
#include <thread>

#include "diagnose/candidate.hpp"

namespace rheomag::diagnose {

std::vector<bool> block_mask(std::size_t n, int blocks, bool even) {
  std::vector<bool> mask(n);
  for (std::size_t k = 0; k < n; ++k) {
    const auto b = static_cast<int>(k * static_cast<std::size_t>(blocks) / n);
    mask[k] = (b % 2 == 0) == even;
  }
  return mask;
}

double heldout_sse(const DiagnosisModel& model, const ModelFit& full, int blocks, int iterations,
                   int threads, const std::vector<bool>& keep) {
  double fold_sse[2] = {0.0, 0.0};
  std::exception_ptr failure[2];
  auto fold = [&](int k) {
    try {
      FitSettings s;
      s.mask = block_mask(model.measured().size(), blocks, k == 0);
      auto other = s.mask;
      other.flip();
      for (std::size_t i = 0; i < keep.size(); ++i) {
        s.mask[i] = s.mask[i] && keep[i];
        other[i] = other[i] && keep[i];
      }
      s.max_iterations = iterations;
      s.threads = threads > 1 ? std::max(threads / 2, 1) : 1;
      s.standard_errors = false;
      s.projected_line_search = true;
      const auto f = fit_model(model, full.effects, full.values, s);
      fold_sse[k] = masked_sse(model.measured(), f.prediction, other);
    } catch (...) {
      failure[k] = std::current_exception();
    }
  };
  if (threads > 1) {
    std::thread second(fold, 1);
    fold(0);
    second.join();
  } else {
    fold(0);
    fold(1);
  }
  for (const auto& e : failure)
    if (e) std::rethrow_exception(e);
  return fold_sse[0] + fold_sse[1];
}

}  // namespace rheomag::diagnose
