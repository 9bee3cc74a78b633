// A fitted model (`rheomag fit --json`) as the diagnosis baseline: its simulated output is the
// baseline prediction, its parameters are held, its output's scale and offset (and the delay
// nuisance) are calibrated, and candidate effects are blocks on its inputs or added to its output
// (Candidate::compose_with_model).

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "diagnose/candidate.hpp"
#include "diagnose/diagnose_model.hpp"

namespace rheomag::diagnose {

namespace {

std::string listed(std::vector<std::string> columns) {
  std::string out;
  for (const auto& c : columns) out += (out.empty() ? "" : ", ") + c;
  return "[" + out + "]";
}

std::vector<std::string> sorted(std::vector<std::string> v) {
  std::sort(v.begin(), v.end());
  return v;
}

}  // namespace

void DiagnosisModel::from_fitted_model(const ModelBaseline& fitted) {
  const auto& meta = rec_.meta;
  const identify::FitModel& m = fitted.model;
  const std::string& file = fitted.file;
  const std::string where = meta.sidecar_path.empty() ? std::string("sidecar") : meta.sidecar_path;
  if (!meta.rig.kind && !m.rig)
    throw InputError(where + ": [rig] kind is not given and " + file +
                     " names no rig either; expected one of constant_velocity_pump, "
                     "bypass_cylinder, damper, coil_bench");
  if (m.rig && meta.rig.kind && *m.rig != *meta.rig.kind)
    throw InputError(file + ": key 'rig': the model was fitted on a " +
                     lumped::rig_kind_name(*m.rig) + " rig, but the recording (" + where +
                     ") is from a " + lumped::rig_kind_name(*meta.rig.kind) +
                     " rig; a model of another rig cannot be its baseline");
  if (sorted(m.drive) != sorted(meta.drive))
    throw InputError(file + ": key 'drive': the model was fitted with drive columns " +
                     listed(m.drive) + ", but the recording (" + where + ") has " +
                     listed(meta.drive) + "; the model cannot be run on it");
  if (m.output != meta.output)
    throw InputError(file + ": key 'output': the model explains '" + m.output +
                     "', but the recording (" + where + ") records '" + meta.output + "'");
  base_.kind = meta.rig.kind ? *meta.rig.kind : *m.rig;
  base_.description = meta.description;
  base_.grid_substeps = kDiagnosisGridSubsteps;
  fitted_ = std::make_shared<const identify::FitModel>(m);
  field_column_ = m.valve_chain ? m.valve_chain->setup.field_column : m.greybox->setup.field_column;
  constant_field_ = field_column_.empty();
  const bool voltage_driven = field_column_ == "command" || field_column_ == "voltage";
  if (voltage_driven) {
    base_.driver_mode = lumped::DriverMode::voltage;
    base_.voltage_column = field_column_;
  }
  includes_.push_back(
      {"fitted_model", 0.0, "",
       file + ": " + (m.valve_chain ? std::string("valve-chain") : std::string("grey-box")) +
           " model '" + m.model + "' of " + m.output + " from " + listed(m.drive) +
           " (its simulated output is the baseline; its parameters are held, its output's "
           "scale and offset calibrated)"});
  const auto& params = m.valve_chain ? m.valve_chain->params : m.greybox->params;
  for (const auto& p : params)
    includes_.push_back({p.name, p.value, p.unit, file + " parameter (held)"});
  if (m.valve_chain)
    includes_.push_back(
        {"static_map", 0.0, "",
         file + " static_map of [valve] case \"" + m.valve_chain->setup.map->case_file + "\" (" +
             std::to_string(m.valve_chain->setup.map->current.size()) + " currents x " +
             std::to_string(m.valve_chain->setup.map->flow.size()) + " flows)"});
  if (meta.coil.resistance) {
    base_.coil.resistance_20c = *meta.coil.resistance;
    includes_.push_back({"coil_resistance", *meta.coil.resistance, "ohm",
                         voltage_driven ? "sidecar [coil] resistance (L/R of the coil_inductance "
                                          "candidate)"
                                        : "sidecar [coil] resistance (no effect: the model reads "
                                          "the current)"});
  }
  base_.coil.inductance = 0.0;
  if (meta.coil.inductance && *meta.coil.inductance > 0.0) {
    base_.coil.inductance = *meta.coil.inductance;
    includes_.push_back({"coil_inductance", *meta.coil.inductance, "H",
                         "sidecar [coil] inductance (stated: the model was fitted to this coil; "
                         "coil_inductance is not a candidate)"});
  }
  if (meta.rig.piston_area)
    base_.piston_area = *meta.rig.piston_area;
  else if (m.valve_chain)
    base_.piston_area = m.valve_chain->setup.piston_area;
  else
    base_.piston_area = 0.0;
  if (base_.piston_area > 0.0)
    includes_.push_back(
        {"piston_area", base_.piston_area, "m^2",
         meta.rig.piston_area ? "sidecar [rig] piston_area" : file + " setup.piston_area"});
  sample_interval_ = median_interval(rec_.t);
  output_ = meta.output;
  measured_ = rec_.column(output_);
  output_rms_ = spread(measured_);
  drive_noise_and_filter();
  if (rec_.columns.count("velocity")) {
    for (double v : rec_.column("velocity"))
      peak_flow_ = std::max(peak_flow_, std::abs(v) * base_.piston_area);
    // The model's sign convention: damping opposes motion, so its output correlates with the
    // velocity with one sign; the output blocks (friction, inertia) take the same sign.
    const auto y = identify::simulate_fit_model(rec_, m);
    const auto& v = rec_.column("velocity");
    double mean = 0.0, dot = 0.0;
    for (double x : y) mean += x / static_cast<double>(y.size());
    for (std::size_t k = 0; k < y.size(); ++k) dot += (y[k] - mean) * v[k];
    model_sign_ = dot < 0.0 ? -1.0 : 1.0;
  }
}

std::vector<double> DiagnosisModel::predict_fitted(const std::vector<const Candidate*>& effects,
                                                   const std::vector<double>& values) const {
  lumped::Recording r = rec_;
  std::vector<double> added(rec_.t.size(), 0.0);
  FittedModelBlocks blocks{r, added, field_column_, model_sign_};
  ParamReader reader(values, static_params().size());
  for (const Candidate* e : effects) e->compose_with_model(blocks, reader, *this);
  auto y = identify::simulate_fit_model(r, *fitted_);
  const double scale = values.at(0), offset = values.at(1);
  for (std::size_t j = 0; j < y.size(); ++j) y[j] = scale * y[j] + offset + added[j];
  return y;
}

}  // namespace rheomag::diagnose
