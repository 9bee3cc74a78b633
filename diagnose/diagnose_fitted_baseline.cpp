// A fitted model (`rheomag fit --json`) as the diagnosis baseline: its simulated output is the
// baseline prediction, its parameters are held, its output's scale and offset (and the delay
// nuisance) are calibrated, and candidate effects are blocks on its inputs (field lags, the coil's
// L/R, magnetic hysteresis) or added to its output (fluid inertia, friction).

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
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

/// First-order lag tau y' = u - y of the samples `u` at times `t`, exact for an input linear
/// between samples; starts at rest (y = u).
std::vector<double> first_order_lag(const std::vector<double>& t, const std::vector<double>& u,
                                    double tau) {
  std::vector<double> y(u.size());
  if (u.empty()) return y;
  y[0] = u[0];
  for (std::size_t k = 0; k + 1 < u.size(); ++k) {
    const double h = t[k + 1] - t[k];
    const double e = std::exp(-h / tau);
    const double slope_tau = h > 0.0 ? (u[k + 1] - u[k]) / h * tau : 0.0;
    y[k + 1] = u[k + 1] - slope_tau + (y[k] - u[k] + slope_tau) * e;
  }
  return y;
}

/// The field-equivalent current of the magnetic_hysteresis candidate (duhem_field(a, d)) along
/// the current path `i`: along a distance x travelled in direction s, dh/dx = a (f - h) + s d with
/// f(i) = i (kDuhemFieldB2 small), integrated exactly on each sample interval.
std::vector<double> duhem_path(const std::vector<double>& i, double a, double d) {
  const lumped::DuhemBlock block = duhem_field(a, d);
  std::vector<double> h(i.size());
  if (i.empty()) return h;
  h[0] = block.b1 * std::tanh(block.b2 * i[0]);
  for (std::size_t k = 0; k + 1 < i.size(); ++k) {
    const double di = i[k + 1] - i[k];
    if (di == 0.0) {
      h[k + 1] = h[k];
      continue;
    }
    const double s = di > 0.0 ? 1.0 : -1.0, x = std::abs(di);
    // Particular solution h_p(x) = f(x) - s (1 - d) / a, f(x) = i_k + s x.
    const double start = i[k] - s * (1.0 - d) / a;
    h[k + 1] = i[k + 1] - s * (1.0 - d) / a + (h[k] - start) * std::exp(-a * x);
  }
  return h;
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

std::vector<double> DiagnosisModel::predict_fitted(const std::vector<Effect>& effects,
                                                   const std::vector<double>& values) const {
  const std::size_t n = rec_.t.size();
  std::size_t k = static_params().size();
  lumped::Recording r = rec_;
  std::vector<double> added(n, 0.0);
  for (Effect e : effects) {
    switch (e) {
      case Effect::mr_response_time:
      case Effect::eddy_currents:
        r.columns[field_column_] = first_order_lag(r.t, r.column(field_column_), values.at(k++));
        break;
      case Effect::coil_inductance:
        r.columns[field_column_] = first_order_lag(r.t, r.column(field_column_),
                                                   values.at(k++) / base_.coil.resistance_20c);
        break;
      case Effect::magnetic_hysteresis:
        r.columns[field_column_] =
            duhem_path(r.column(field_column_), values.at(k), values.at(k + 1));
        k += 2;
        break;
      case Effect::fluid_inertia: {
        // L dQ/dt on the pressure; on a damper's force, A L dQ/dt (Q = A v).
        const double area = base_.piston_area;
        const double gain = model_sign_ * values.at(k++) * area *
                            (base_.kind == lumped::RigKind::damper ? area : 1.0);
        const auto& v = rec_.column("velocity");
        for (std::size_t j = 1; j + 1 < n; ++j)
          added[j] += gain * (v[j + 1] - v[j - 1]) / (rec_.t[j + 1] - rec_.t[j - 1]);
        break;
      }
      case Effect::friction: {
        const double force = model_sign_ * values.at(k++);
        const auto& v = rec_.column("velocity");
        for (std::size_t j = 0; j < n; ++j)
          added[j] += force * std::tanh(v[j] / base_.friction_velocity);
        break;
      }
      default:
        throw InputError("diagnose: " + effect_name(e) +
                         " cannot be composed with a fitted-model baseline");
    }
  }
  auto y = identify::simulate_fit_model(r, *fitted_);
  const double scale = values.at(0), offset = values.at(1);
  for (std::size_t j = 0; j < n; ++j) y[j] = scale * y[j] + offset + added[j];
  return y;
}

}  // namespace rheomag::diagnose
