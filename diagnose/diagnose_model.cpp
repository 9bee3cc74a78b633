// Baseline rig from a recording's sidecar and the parameter layout of candidate physics.

#include "diagnose/diagnose_model.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

#include "core/error.hpp"

namespace rheomag::diagnose {

using lumped::DriverMode;
using lumped::RigKind;
using lumped::RigSpec;

std::string effect_name(Effect effect) {
  switch (effect) {
    case Effect::compressibility:
      return "compressibility";
    case Effect::fluid_inertia:
      return "fluid_inertia";
    case Effect::magnetic_hysteresis:
      return "magnetic_hysteresis";
    case Effect::eddy_currents:
      return "eddy_currents";
    case Effect::coil_inductance:
      return "coil_inductance";
    case Effect::coil_heating:
      return "coil_heating";
    case Effect::mr_response_time:
      return "mr_response_time";
    case Effect::friction:
      return "friction";
  }
  return "";
}

namespace {

double rms(const std::vector<double>& v) {
  double s = 0.0;
  for (double x : v) s += x * x;
  return v.empty() ? 0.0 : std::sqrt(s / static_cast<double>(v.size()));
}

bool has(const std::vector<std::string>& list, const std::string& name) {
  return std::find(list.begin(), list.end(), name) != list.end();
}

}  // namespace

DiagnosisModel::DiagnosisModel(const lumped::Recording& rec) : rec_(rec) {
  const auto& meta = rec.meta;
  const std::string where = meta.sidecar_path.empty() ? std::string("sidecar") : meta.sidecar_path;
  if (!meta.rig.kind)
    throw InputError(where +
                     ": [rig] kind is not given; expected one of constant_velocity_pump, "
                     "bypass_cylinder, damper, coil_bench; the baseline needs the rig layout");
  base_.kind = *meta.rig.kind;
  const std::string kind_name = lumped::rig_kind_name(base_.kind);
  base_.description = meta.description;
  base_.grid_substeps = kDiagnosisGridSubsteps;
  // Driver: an imposed current, or a voltage-driven coil, or an (ideally tracked) current command.
  if (has(meta.drive, "current")) {
    base_.driver_mode = DriverMode::current_source;
  } else if (has(meta.drive, "voltage") || has(meta.drive, "command")) {
    base_.driver_mode = DriverMode::voltage;
    base_.voltage_column = has(meta.drive, "voltage") ? "voltage" : "command";
    auto gain = meta.rig.extra.find("driver_gain");
    base_.driver.gain = gain != meta.rig.extra.end() ? gain->second : 1.0;
    if (!meta.coil.resistance)
      throw InputError(where +
                       ": [coil] resistance is missing; the baseline of a voltage-driven "
                       "coil needs it to turn voltage into current");
  } else if (has(meta.drive, "current_cmd")) {
    // Ideal current control: the coil current equals the command.
    base_.driver_mode = DriverMode::current_source;
    rec_.columns["current"] = rec.column("current_cmd");
  } else {
    // No coil input recorded: the field is taken as constant and the static map's top current
    // stands for it (the calibrated yield scale absorbs the actual level).
    if (meta.valve.yield_current.empty())
      throw InputError(where +
                       ": [recording] drive names no coil input (current, current_cmd, "
                       "voltage or command) and [valve] has no yield_current table");
    base_.driver_mode = DriverMode::current_source;
    rec_.columns["current"].assign(rec.t.size(), meta.valve.yield_current.back());
    constant_field_ = true;
  }
  if (meta.coil.resistance) base_.coil.resistance_20c = *meta.coil.resistance;
  base_.coil.inductance = 0.0;  // ideal coil
  if (base_.kind != RigKind::coil_bench) {
    if (!has(meta.drive, "velocity"))
      throw InputError(where + ": [recording] drive must include velocity for a " + kind_name +
                       " rig");
    if (!meta.rig.piston_area)
      throw InputError(where +
                       ": [rig] piston_area is missing; the baseline needs it to turn "
                       "velocity into flow");
    base_.piston_area = *meta.rig.piston_area;
    if (meta.valve.yield_current.empty() || meta.valve.yield_pressure.empty()) {
      if (!meta.valve.case_file.empty())
        throw InputError(where + ": [valve] case = \"" + meta.valve.case_file +
                         "\": diagnose needs the static map (yield_current, yield_pressure, "
                         "viscous_resistance); run the FE chain and give the map");
      throw InputError(where +
                       ": [valve] yield_current and yield_pressure are missing; the "
                       "baseline needs the valve's static map");
    }
    if (!meta.valve.viscous_resistance)
      throw InputError(where + ": [valve] viscous_resistance is missing; the baseline needs it");
    base_.valve.yield_current = meta.valve.yield_current;
    base_.valve.yield_pressure = meta.valve.yield_pressure;
    base_.valve.viscous_resistance = *meta.valve.viscous_resistance;
    if (meta.rig.chamber_volume) {
      chamber_volume_ = *meta.rig.chamber_volume;
      chamber_volume_given_ = true;
    }
    if (base_.kind == RigKind::damper) {
      base_.rod_area = meta.rig.rod_area.value_or(0.0);
      base_.gas_force = meta.rig.gas_force.value_or(0.0);
    }
  }
  output_ = lumped::rig_output_column(base_);
  if (meta.output != output_)
    throw InputError(where + ": [recording] output = \"" + meta.output + "\" but a " + kind_name +
                     " rig explains \"" + output_ + "\"");
  measured_ = rec_.column(output_);
  // [rig] orientation = -1: the output is recorded with the opposite sign (e.g. mrdamper).
  if (auto o = meta.rig.extra.find("orientation"); o != meta.rig.extra.end()) {
    if (o->second != 1.0 && o->second != -1.0)
      throw InputError(where + ": [rig] orientation must be 1 or -1");
    for (double& y : measured_) y *= o->second;
  }
  for (const auto& c : lumped::rig_drive_columns(base_)) (void)rec_.column(c);
  const double mean = std::accumulate(measured_.begin(), measured_.end(), 0.0) /
                      static_cast<double>(measured_.size());
  double var = 0.0;
  for (double y : measured_) var += (y - mean) * (y - mean);
  output_rms_ = std::max(std::sqrt(var / static_cast<double>(measured_.size())), 1e-300);
}

lumped::DuhemBlock duhem_field(double a, double d) {
  lumped::DuhemBlock h;
  h.a = a;
  h.d = d;
  h.b2 = kDuhemFieldB2;
  h.b1 = 1.0 / kDuhemFieldB2;  // f(i) = b1 tanh(b2 i) = i within 0.01 % up to 1 A
  h.flux_per_ampere = 1.0;     // lambda is the field-equivalent current
  return h;
}

std::vector<Effect> DiagnosisModel::applicable_effects() const {
  std::vector<Effect> out;
  if (base_.kind != RigKind::coil_bench) {
    out.push_back(Effect::compressibility);
    // Inertia needs acceleration: not on a constant-velocity drive.
    const auto& v = rec_.column("velocity");
    const auto [vmin, vmax] = std::minmax_element(v.begin(), v.end());
    if (*vmax - *vmin > 1e-6 * std::max(std::abs(*vmax), std::abs(*vmin)))
      out.push_back(Effect::fluid_inertia);
    out.push_back(Effect::mr_response_time);
    out.push_back(Effect::eddy_currents);
    // Duhem between an imposed (or ideally tracked) current and the field; a voltage-driven coil
    // would need the hysteresis inside the inductor instead (not a candidate).
    if (base_.driver_mode == DriverMode::current_source && !constant_field_)
      out.push_back(Effect::magnetic_hysteresis);
  }
  if (base_.driver_mode == DriverMode::voltage) {
    out.push_back(Effect::coil_inductance);
    out.push_back(Effect::coil_heating);
  }
  if (base_.kind == RigKind::damper) out.push_back(Effect::friction);
  return out;
}

std::vector<ParamDef> DiagnosisModel::static_params() const {
  std::vector<ParamDef> p;
  if (base_.kind == RigKind::coil_bench) {
    const double r = base_.coil.resistance_20c;
    p.push_back({"coil_resistance", r, 0.2 * r, 5.0 * r, true, 1.0});
    return p;
  }
  p.push_back({"yield_scale", 1.0, 0.05, 20.0, false, 1.0});
  const double rv = base_.valve.viscous_resistance;
  p.push_back({"viscous_resistance", rv, rv * 1e-2, rv * 1e2, true, 1.0});
  if (base_.kind == RigKind::damper)
    p.push_back({"force_offset", base_.gas_force, base_.gas_force - 10.0 * output_rms_,
                 base_.gas_force + 10.0 * output_rms_, false, output_rms_});
  return p;
}

std::vector<ParamDef> DiagnosisModel::effect_params(Effect effect) const {
  const double duration = rec_.t.back() - rec_.t.front();
  switch (effect) {
    case Effect::compressibility: {
      const double v = chamber_volume_;
      return {{"air_volume", 1e-3 * v, 1e-8 * v, v, true, 1.0}};
    }
    case Effect::fluid_inertia: {
      // Start where the inertial pressure is a tenth of the measured swing.
      const auto& vel = rec_.column("velocity");
      std::vector<double> acc(vel.size(), 0.0);
      for (std::size_t k = 1; k + 1 < vel.size(); ++k)
        acc[k] = (vel[k + 1] - vel[k - 1]) / (rec_.t[k + 1] - rec_.t[k - 1]);
      double scale = 0.1 * output_rms_ / std::max(rms(acc) * base_.piston_area, 1e-300);
      if (base_.kind == RigKind::damper) scale /= base_.piston_area;
      return {{"inertance", scale, scale * 1e-5, scale * 1e4, true, 1.0}};
    }
    case Effect::eddy_currents:
    case Effect::mr_response_time:
      return {{"time_constant", 0.01, 1e-5, 10.0, true, 1.0}};
    case Effect::coil_inductance:
      return {{"inductance", 0.1, 1e-5, 100.0, true, 1.0}};
    case Effect::coil_heating:
      return {{"thermal_resistance", 2.0, 1e-2, 1e3, true, 1.0},
              {"thermal_time_constant", duration, 1e-2 * duration, 1e3 * duration, true, 1.0}};
    case Effect::friction:
      return {
          {"coulomb_force", 0.05 * output_rms_, 1e-6 * output_rms_, 10.0 * output_rms_, true, 1.0}};
    case Effect::magnetic_hysteresis: {
      // Duhem in field-equivalent amperes: a [1/A] (a large a closes the loop), d [-] the
      // reversible fraction of the slope; the loop's half width is (1 - d) / a.
      const auto& i = rec_.column("current");
      const auto [lo, hi] = std::minmax_element(i.begin(), i.end());
      const double range = std::max(*hi - *lo, 1e-6);
      return {{"a", 10.0 / range, 0.3 / range, 3e3 / range, true, 1.0},
              {"d", 0.5, 0.0, 0.98, false, 1.0}};
    }
  }
  throw InputError("diagnose: no candidate model for " + effect_name(effect));
}

std::vector<ParamDef> DiagnosisModel::layout(const std::vector<Effect>& effects) const {
  auto out = static_params();
  for (Effect e : effects) {
    auto p = effect_params(e);
    out.insert(out.end(), p.begin(), p.end());
  }
  return out;
}

RigSpec DiagnosisModel::spec(const std::vector<Effect>& effects,
                             const std::vector<double>& values) const {
  RigSpec s = base_;
  std::size_t k = 0;
  if (s.kind == RigKind::coil_bench) {
    s.coil.resistance_20c = values.at(k++);
  } else {
    s.valve.yield_scale = values.at(k++);
    s.valve.viscous_resistance = values.at(k++);
    if (s.kind == RigKind::damper) s.gas_force = values.at(k++);
  }
  for (Effect e : effects) {
    switch (e) {
      case Effect::compressibility: {
        lumped::ChamberBlock chamber;
        chamber.oil_volume = chamber_volume_;
        chamber.air_volume = values.at(k++);
        s.compressibility = chamber;
        break;
      }
      case Effect::fluid_inertia:
        s.inertance = values.at(k++);
        break;
      case Effect::eddy_currents:
        s.eddy_time_constant = values.at(k++);
        break;
      case Effect::mr_response_time:
        s.mr_response_time = values.at(k++);
        break;
      case Effect::coil_inductance:
        s.coil.inductance = values.at(k++);
        break;
      case Effect::coil_heating: {
        lumped::ThermalBlock thermal;
        thermal.thermal_resistance = values.at(k++);
        thermal.thermal_time_constant = values.at(k++);
        s.coil_heating = thermal;
        break;
      }
      case Effect::friction:
        s.coulomb_force = values.at(k++);
        break;
      case Effect::magnetic_hysteresis:
        s.magnetic_hysteresis = duhem_field(values.at(k), values.at(k + 1));
        k += 2;
        break;
    }
  }
  return s;
}

std::vector<double> DiagnosisModel::predict(const std::vector<Effect>& effects,
                                            const std::vector<double>& values) const {
  const auto sim = lumped::simulate_rig(spec(effects, values), rec_);
  return sim.columns.at(output_);
}

std::vector<double> DiagnosisModel::predict_column(const std::vector<Effect>& effects,
                                                   const std::vector<double>& values,
                                                   const std::string& column) const {
  const auto sim = lumped::simulate_rig(spec(effects, values), rec_);
  return sim.columns.at(column);
}

}  // namespace rheomag::diagnose
