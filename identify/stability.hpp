#pragma once
// Simulation stability of an identified black-box model: the poles of its linear output
// recursion (where it has one) and a bounded free-run response on given data. A model that fails
// either has no meaningful simulation FIT, so the CLI reports the verdict instead.

#include <optional>
#include <string>

#include "identify/black_box_model.hpp"
#include "identify/io_data.hpp"

namespace rheomag::identify {

/// Verdict of check_simulation_stability.
struct StabilityVerdict {
  bool stable = true;
  std::string reason;                 ///< why not (empty when stable)
  std::optional<double> pole_radius;  ///< largest |pole| of the linear output recursion, if any
  double peak_ratio = 0.0;            ///< max |yhat - mean(y)| / max |y - mean(y)| of the free run
};

/// Largest root modulus of z^n + c[0] z^(n-1) + ... + c[n-1] (companion-matrix eigenvalues);
/// 0 for an empty c.
double largest_root_modulus(const std::vector<double>& c);

/// Checks `model` in free-run simulation on `data`: the poles of its linear output recursion
/// (ARX's A(q), Hammerstein-Wiener's F(q), NARX's linear terms y(k-i): its linearisation about
/// the mean) must lie inside the unit circle, and the simulated
/// output must stay finite and within `peak_limit` times the measured peak deviation from the
/// mean.
StabilityVerdict check_simulation_stability(const IdentModel& model, const IoData& data,
                                            double peak_limit = 10.0);

}  // namespace rheomag::identify
