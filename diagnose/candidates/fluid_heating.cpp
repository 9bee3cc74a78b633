// The fluid_heating candidate: the valve's dissipated power dp Q warms the fluid over a long
// recording and its viscosity falls, so the viscous part of the force or pressure drifts down
// (the yield part stays). coil_heating, by contrast, drifts the current of a voltage-driven coil.

#include <algorithm>
#include <cmath>
#include <sstream>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose::candidates {

namespace {

/// [W] Mean power the recording dissipates: |output x velocity|, times the piston area when the
/// output is a pressure (dp Q = dp A v).
double mean_dissipated_power(const DiagnosisModel& model) {
  const auto& y = model.measured();
  const auto& v = model.recording().column("velocity");
  const double area = model.output_column() == "pressure" ? model.baseline().piston_area : 1.0;
  double sum = 0.0;
  for (std::size_t k = 0; k < y.size() && k < v.size(); ++k) sum += std::abs(y[k] * v[k]) * area;
  return sum / static_cast<double>(std::max<std::size_t>(y.size(), 1));
}

/// [s] Mean flow cycle of the recording: twice its duration over the number of velocity
/// reversals beyond a band of five noise standard deviations and 1 % of the peak (0: fewer than
/// two reversals).
double flow_cycle(const DiagnosisModel& model) {
  const auto& t = model.recording().t;
  const auto& v = model.recording().column("velocity");
  if (t.size() < 2 || v.empty()) return 0.0;
  double peak = 0.0;
  for (double x : v) peak = std::max(peak, std::abs(x));
  const auto noise = model.drive_noise().find("velocity");
  const double band =
      std::max(0.01 * peak, noise == model.drive_noise().end() ? 0.0 : 5.0 * noise->second);
  int sign = 0, reversals = 0;
  for (double x : v) {
    const int s = x > band ? 1 : x < -band ? -1 : 0;
    if (s != 0 && sign != 0 && s != sign) ++reversals;
    if (s != 0) sign = s;
  }
  return reversals < 2 ? 0.0 : 2.0 * (t.back() - t.front()) / reversals;
}

/// Lower bound of the thermal time constant, as a fraction of the recording's duration.
constexpr double kMinTimeConstantFraction = 1e-2;

class FluidHeating final : public Candidate {
 public:
  std::string name() const override { return "fluid_heating"; }

  bool applies(const DiagnosisModel& model) const override {
    // The rig model's valve map has an explicit viscous part to thin; a fitted model has none.
    return !model.fitted_baseline() && model.baseline().kind != lumped::RigKind::coil_bench &&
           model.recording().columns.count("velocity") && mean_dissipated_power(model) > 0.0;
  }

  std::vector<ParamDef> params(const DiagnosisModel& model) const override {
    // Start: a resistance whose steady rise at the mean power is 5 K (10 % thinner at the stated
    // slope), a time constant of the recording's length; bounds three decades either side.
    const auto& t = model.recording().t;
    const double duration = t.back() - t.front();
    const double resistance = 5.0 / mean_dissipated_power(model);
    return {
        {"thermal_resistance", resistance, 1e-3 * resistance, 1e3 * resistance, true, 1.0, "K/W"},
        {"thermal_time_constant", duration, kMinTimeConstantFraction * duration, 1e3 * duration,
         true, 1.0, "s"}};
  }

  std::string implausible(const DiagnosisModel& model, const ModelFit& fit) const override {
    // A heat store that fills and empties within one flow cycle (or at the bottom of the time
    // constant's range) stores nothing: the viscous part would follow the power of the moment,
    // which is the valve law's own shape (its knee, a shear-thinning fluid), not a warming.
    const double tau = fit_value(fit, "thermal_time_constant");
    const auto& t = model.recording().t;
    const double cycle = flow_cycle(model);
    const double lowest = 2.0 * kMinTimeConstantFraction * (t.back() - t.front());
    if (!(tau < std::max(cycle, lowest))) return "";
    return " with a thermal time constant of " + fmt(tau) + " s, shorter than " +
           (cycle > lowest ? "one flow cycle (" + fmt(cycle) + " s)"
                           : "twice the lowest it may take (" + fmt(lowest) + " s)") +
           ": the viscous part follows the power of the moment, a shape of the valve law (its "
           "knee, a shear-thinning fluid), not a warming; not accepted";
  }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& /*model*/) const override {
    lumped::FluidHeatingBlock heating;
    heating.thermal_resistance = values.next();
    heating.thermal_time_constant = values.next();
    spec.fluid_heating = heating;
  }

  std::string evidence(const Diagnosis& /*d*/, const ModelFit& fit) const override {
    const double resistance = fit_value(fit, "thermal_resistance");
    std::ostringstream o;
    o << "the residual drifts with the energy the valve has dissipated and grows with the flow "
         "(the viscous part thins, the yield part stays); the fluid warming with thermal "
         "resistance "
      << fmt(resistance) << " K/W and time constant "
      << fmt(fit_value(fit, "thermal_time_constant"))
      << " s explains it, at the stated viscosity slope of "
      << fmt(100 * lumped::kFluidViscosityTemperatureSlope, 2)
      << " %/K (only their product, a steady viscosity change of "
      << fmt(100 * viscosity_change_per_watt(resistance), 2)
      << " % per watt dissipated, is measured)";
    return o.str();
  }

  std::string separating_measurement(const Candidate& other) const override {
    if (other.name() != "coil_heating") return "";
    return "record the fluid (or housing) temperature and the coil current: fluid heating thins "
           "the viscous part at an unchanged current, coil heating lowers the current of a "
           "voltage-driven coil and with it the yield part";
  }

  std::vector<DerivedParam> derived_params(const DiagnosisModel& /*model*/,
                                           const std::vector<double>& params) const override {
    return {{"viscosity_change_per_watt", viscosity_change_per_watt(params.at(0)), "1/W"}};
  }

 private:
  /// Relative steady viscosity change per watt dissipated at the stated slope (negative).
  static double viscosity_change_per_watt(double thermal_resistance) {
    return std::expm1(-lumped::kFluidViscosityTemperatureSlope * thermal_resistance);
  }
};

}  // namespace

/// The fluid_heating candidate (registered in candidate_registry.cpp).
const Candidate& fluid_heating() {
  static const FluidHeating candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
