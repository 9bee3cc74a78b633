// The compressibility candidate: air entrained in the chambers' oil, a compliance that must be
// compressed before pressure can build (largest at flow reversals).

#include <sstream>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"
#include "lumped/blocks.hpp"

namespace rheomag::diagnose::candidates {

namespace {

class Compressibility final : public Candidate {
 public:
  std::string name() const override { return "compressibility"; }

  bool applies(const DiagnosisModel& model) const override {
    // A chamber sits inside the rig's hydraulic loop: not a block on a fitted model.
    return !model.fitted_baseline() && model.baseline().kind != lumped::RigKind::coil_bench;
  }

  std::vector<ParamDef> params(const DiagnosisModel& model) const override {
    const double v = model.chamber_volume();
    return {{"air_volume", 1e-3 * v, 1e-8 * v, v, true, 1.0, "m^3"}};
  }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& model) const override {
    // On top of the stated oil (and of a pre-yield compliance): the chamber's air.
    lumped::ChamberBlock chamber = spec.compressibility.value_or(lumped::ChamberBlock{});
    chamber.oil_volume = model.chamber_volume();
    chamber.air_volume = values.next();
    spec.compressibility = chamber;
  }

  std::string evidence(const Diagnosis& d, const ModelFit& fit) const override {
    std::ostringstream o;
    o << "the output lags the baseline by " << fmt(1e3 * d.baseline_stats.output_lag) << " ms; "
      << fmt(100 * regime_share(d.mismatch, "flow reversal"), 2)
      << " % of the residual energy sits at flow reversals, where a chamber with "
      << fmt(fit_value(fit, "air_volume")) << " m^3 of air per chamber ("
      << fmt(lumped::kRigChambers * fit_value(fit, "air_volume"))
      << " m^3 in both) must be compressed before pressure can build";
    return o.str();
  }

  std::string separating_measurement(const Candidate& other) const override {
    if (other.name() == "pre_yield")
      return "repeat at two amplitudes: entrained air stiffens as the pressure rises (isothermal "
             "compliance V/p falls with the pressure), the elastic pre-yield branch does not; a "
             "chamber pressure transducer shows air's curved pressure-volume path directly";
    if (other.name() == "fluid_inertia")
      return "change the frequency: a compliance lag shrinks with stiffer fluid and grows with "
             "the pressure swing, inertia grows with the square of the frequency";
    return "";
  }

  std::vector<DerivedParam> derived_params(const DiagnosisModel& /*model*/,
                                           const std::vector<double>& params) const override {
    if (params.empty()) return {};
    // The rig's loop has two chambers, each with this air: a rig spec (`air_volume`, split over
    // the chambers) or another tool states the total. The capacitance is one chamber's,
    // isothermal air at the 1e5 Pa precharge.
    return {{"total_air_volume", lumped::kRigChambers * params[0], "m^3"},
            {"hydraulic_capacitance", params[0] / 1e5, "m^3/Pa"}};
  }

  bool uses_chamber_volume() const override { return true; }
};

}  // namespace

/// The compressibility candidate (registered in candidate_registry.cpp).
const Candidate& compressibility() {
  static const Compressibility candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
