// The fluid_inertia candidate: the inertance of the oil column, a pressure (or damper force)
// that follows the piston acceleration.

#include <algorithm>
#include <cmath>
#include <sstream>

#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_ringing.hpp"
#include "diagnose/diagnose_run.hpp"
#include "diagnose/diagnose_text.hpp"

namespace rheomag::diagnose::candidates {

namespace {

double rms(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return v.empty() ? 0.0 : std::sqrt(s / static_cast<double>(v.size()));
}

class FluidInertia final : public Candidate {
 public:
  std::string name() const override { return "fluid_inertia"; }

  bool applies(const DiagnosisModel& model) const override {
    const auto& rig = model.baseline();
    const auto& rec = model.recording();
    if (rig.kind == lumped::RigKind::coil_bench) return false;
    if (model.fitted_baseline() && !(rig.piston_area > 0.0 && rec.columns.count("velocity")))
      return false;
    // Inertia needs acceleration: not on a constant-velocity drive (a velocity that moves only
    // by its noise is constant).
    const auto& v = rec.column("velocity");
    const auto [vmin, vmax] = std::minmax_element(v.begin(), v.end());
    const auto& noises = model.drive_noise();
    const double noise = noises.count("velocity") ? noises.at("velocity") : 0.0;
    if (model.fitted_baseline()) return *vmax - *vmin > 10.0 * noise;
    return *vmax - *vmin >
           std::max(10.0 * noise, 1e-6 * std::max(std::abs(*vmax), std::abs(*vmin)));
  }

  std::vector<ParamDef> params(const DiagnosisModel& model) const override {
    // Start where the inertial pressure is a tenth of the measured swing.
    const auto& rec = model.recording();
    const auto& rig = model.baseline();
    const auto& vel = rec.column("velocity");
    std::vector<double> acc(vel.size(), 0.0);
    for (std::size_t k = 1; k + 1 < vel.size(); ++k)
      acc[k] = (vel[k + 1] - vel[k - 1]) / (rec.t[k + 1] - rec.t[k - 1]);
    double scale = 0.1 * model.output_spread() / std::max(rms(acc) * rig.piston_area, 1e-300);
    if (rig.kind == lumped::RigKind::damper) scale /= rig.piston_area;
    return {{"inertance", scale, scale * 1e-5, scale * 1e4, true, 1.0, "Pa s^2/m^3"}};
  }

  void switch_on(lumped::RigSpec& spec, ParamReader& values,
                 const DiagnosisModel& /*model*/) const override {
    spec.inertance = values.next();
  }

  bool composes_with_fitted_model() const override { return true; }

  bool linear_in_size(const DiagnosisModel& model) const override {
    return model.fitted_baseline();  // a term added to the fitted model's output
  }

  void compose_with_model(FittedModelBlocks& blocks, ParamReader& values,
                          const DiagnosisModel& model) const override {
    // L dQ/dt on the pressure; on a damper's force, A L dQ/dt (Q = A v).
    const auto& rec = model.recording();
    const double area = model.baseline().piston_area;
    const double gain = blocks.sign * values.next() * area *
                        (model.baseline().kind == lumped::RigKind::damper ? area : 1.0);
    const auto& v = rec.column("velocity");
    for (std::size_t j = 1; j + 1 < rec.t.size(); ++j)
      blocks.added_output[j] += gain * (v[j + 1] - v[j - 1]) / (rec.t[j + 1] - rec.t[j - 1]);
  }

  std::vector<DerivedParam> derived_params(const DiagnosisModel& model,
                                           const std::vector<double>& params) const override {
    // On a damper the force is A^2 L a: the moving mass the inertance stands for [kg].
    const double area = model.baseline().piston_area;
    if (params.empty() || model.baseline().kind != lumped::RigKind::damper || !(area > 0.0))
      return {};
    return {{"moving_mass", params[0] * area * area, "kg"}};
  }

  std::string evidence(const Diagnosis& d, const ModelFit& fit) const override {
    std::ostringstream o;
    const double lag_ms = 1e3 * d.baseline_stats.output_lag;
    o << "the residual follows the piston acceleration (";
    if (lag_ms < 0.0)
      o << "the output leads the baseline by " << fmt(-lag_ms) << " ms";
    else
      o << "the output lags the baseline by " << fmt(lag_ms)
        << " ms overall, which inertia alone would not do";
    o << "); an inertance of " << fmt(fit_value(fit, "inertance")) << " Pa s^2/m^3 explains it";
    return o.str();
  }

  std::vector<double> measured_starts(const DiagnosisModel& model,
                                      const ModelFit& current) const override {
    // With a compliance in the model the error is multimodal in the inertance: it is also
    // started at the ringing the residual shows (omega^2 = 1 / (I C)).
    return ringing_inertances(model, current, params(model).front());
  }
};

}  // namespace

/// The fluid_inertia candidate (registered in candidate_registry.cpp).
const Candidate& fluid_inertia() {
  static const FluidInertia candidate;
  return candidate;
}

}  // namespace rheomag::diagnose::candidates
