// The gas_spring candidate: a damper force proportional to the piston displacement, as the
// accumulator's gas pressing on the rod volume gives (or any stiffness in parallel with the
// damper: a mount, a spring element of the rig). On a fitted-model baseline only: on a sidecar
// rig the chambers' compliance (compressibility, pre_yield) is the stiffness in the hydraulic loop.

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose::candidates {

namespace {

/// Mean of `v`.
double mean_of(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x;
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}

/// Root mean square of `v` about its mean.
double spread_of(const std::vector<double>& v) {
  const double m = mean_of(v);
  double s = 0.0;
  for (double x : v) s += (x - m) * (x - m);
  return v.empty() ? 0.0 : std::sqrt(s / static_cast<double>(v.size()));
}

class GasSpring final : public Candidate {
 public:
  std::string name() const override { return "gas_spring"; }

  bool applies(const DiagnosisModel& model) const override {
    // A damper's force on a fitted model, with a displacement that moves beyond its noise.
    if (!model.fitted_baseline() || model.baseline().kind != lumped::RigKind::damper) return false;
    const auto& rec = model.recording();
    if (!rec.columns.count("displacement")) return false;
    const auto& x = rec.column("displacement");
    const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
    const auto& noises = model.drive_noise();
    const double noise = noises.count("displacement") ? noises.at("displacement") : 0.0;
    return *hi - *lo > 10.0 * noise && *hi > *lo;
  }

  std::vector<ParamDef> params(const DiagnosisModel& model) const override {
    // Start where the spring force is a twentieth of the output's spread.
    const double x_rms = spread_of(model.recording().column("displacement"));
    const double k = 0.05 * model.output_spread() / std::max(x_rms, 1e-300);
    return {{"stiffness", k, 1e-6 * k, 1e3 * k, true, 1.0, "N/m"}};
  }

  void switch_on(lumped::RigSpec& /*spec*/, ParamReader& /*values*/,
                 const DiagnosisModel& /*model*/) const override {
    throw std::logic_error("gas_spring is a candidate on a fitted-model baseline only");
  }

  bool composes_with_fitted_model() const override { return true; }

  bool linear_in_size(const DiagnosisModel& model) const override {
    return model.fitted_baseline();  // a term added to the fitted model's output
  }

  void compose_with_model(FittedModelBlocks& blocks, ParamReader& values,
                          const DiagnosisModel& model) const override {
    // k (x - mean x): the constant part is the calibrated offset's.
    const double k = blocks.sign * values.next();
    const auto& x = model.recording().column("displacement");
    const double centre = mean_of(x);
    for (std::size_t j = 0; j < x.size(); ++j) blocks.added_output[j] += k * (x[j] - centre);
  }

  std::string evidence(const Diagnosis& /*d*/, const ModelFit& fit) const override {
    std::ostringstream o;
    o << "the residual follows the piston displacement (in phase with it, a quarter cycle behind "
         "the velocity); a stiffness of "
      << fmt(fit_value(fit, "stiffness"))
      << " N/m in parallel with the model explains it (an accumulator's gas spring on the rod "
         "volume, or a compliant mount)";
    return o.str();
  }

  std::string separating_measurement(const Candidate& other) const override {
    if (other.name() != "fluid_inertia") return "";
    return "repeat at another frequency: on one sinusoid a mass m and a negative stiffness "
           "-m w^2 give the same force; a spring's force keeps its size with the frequency, an "
           "inertia's grows with its square";
  }
};

}  // namespace

/// The gas_spring candidate (registered in candidate_registry.cpp).
const Candidate& gas_spring() {
  static const GasSpring candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
