// Parsing of simulation specs (TOML) and their simulation.

#include "coupling/simulation_spec.hpp"
#include "core/input_file.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <set>
#include <sstream>

#include "case/case_file.hpp"
#include "core/error.hpp"
#include "core/quantity_domain.hpp"
#include "coupling/field_lag_prediction.hpp"
#include "coupling/rig_chain_map.hpp"
#include "lumped/lugre_paper001.hpp"
#include "lumped/transfer_function.hpp"
#include "valve/coil.hpp"

namespace rheomag::coupling {

namespace {

/// Reads keys of one table with errors naming the file and key.
class TableReader {
 public:
  TableReader(const toml::table* table, std::string file, std::string name)
      : table_(table), file_(std::move(file)), name_(std::move(name)) {}
  bool present() const { return table_ != nullptr; }
  bool has(const std::string& key) const { return table_ && table_->contains(key); }
  [[noreturn]] void fail(const std::string& key, const std::string& what) const {
    throw InputError(file_ + ": [" + name_ + "] " + key + " " + what);
  }
  double number(const std::string& key, double fallback, double lower = -HUGE_VAL,
                bool strict = false) const {
    if (!has(key)) return fallback;
    auto v = (*table_)[key].value<double>();
    if (!v || !std::isfinite(*v)) fail(key, "must be a finite number");
    if (strict ? !(*v > lower) : !(*v >= lower))
      fail(key, std::string("must be ") + (strict ? "> " : ">= ") + std::to_string(lower));
    return *v;
  }
  double positive(const std::string& key, double fallback) const {
    return number(key, fallback, 0.0, true);
  }
  /// A number in `domain`, or `fallback` when absent; `why` says where the domain comes from.
  double within(const std::string& key, const Domain& domain, double fallback,
                const std::string& why) const {
    const double v = number(key, fallback);
    const std::string violation = domain.violation(v);
    if (!violation.empty()) fail(key, violation + " (" + why + ")");
    return v;
  }
  std::string text(const std::string& key, const std::string& fallback) const {
    if (!has(key)) return fallback;
    auto v = (*table_)[key].value<std::string>();
    if (!v) fail(key, "must be a string");
    return *v;
  }
  bool flag(const std::string& key, bool fallback) const {
    if (!has(key)) return fallback;
    auto v = (*table_)[key].value<bool>();
    if (!v) fail(key, "must be true or false");
    return *v;
  }
  std::vector<double> numbers(const std::string& key) const {
    std::vector<double> out;
    if (!has(key)) return out;
    const toml::array* arr = (*table_)[key].as_array();
    if (!arr) fail(key, "must be an array of numbers");
    for (const auto& e : *arr) {
      auto v = e.value<double>();
      if (!v || !std::isfinite(*v)) fail(key, "must contain only finite numbers");
      out.push_back(*v);
    }
    return out;
  }
  const toml::table* sub(const std::string& key) const {
    if (!has(key)) return nullptr;
    const toml::table* t = (*table_)[key].as_table();
    if (!t) fail(key, "must be a table");
    return t;
  }
  void only(const std::set<std::string>& allowed) const {
    if (!table_) return;
    for (const auto& [k, v] : *table_) {
      std::string key(k.str());
      if (!allowed.count(key)) {
        std::string list;
        for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
        fail(key, "is not a known key (expected one of: " + list + ")");
      }
    }
  }
  const std::string& file() const { return file_; }

 private:
  const toml::table* table_;
  std::string file_, name_;
};

/// Reads an effect table; an effect is on when its table is present and `enabled` is not false.
bool effect_on(const TableReader& t) {
  return t.present() && t.flag("enabled", true);
}

lumped::RigSpec read_rig(const toml::table& doc, const std::string& file) {
  lumped::RigSpec s;
  TableReader rig(doc["rig"].as_table(), file, "rig");
  rig.only({"kind", "description", "piston_area", "rod_area", "gas_force", "bore", "rod"});
  if (!lumped::parse_rig_kind(rig.text("kind", ""), s.kind))
    rig.fail("kind", "must be constant_velocity_pump, bypass_cylinder, damper or coil_bench");
  s.description = rig.text("description", "");
  if (rig.has("bore")) {
    const double pi = 3.14159265358979323846, bore = rig.positive("bore", 0.03),
                 rod = rig.number("rod", 0.0, 0.0);
    if (!(rod < bore)) rig.fail("rod", "must be smaller than bore");
    s.piston_area = pi / 4 * (bore * bore - rod * rod);
  }
  s.piston_area = rig.positive("piston_area", s.piston_area);
  s.rod_area = rig.number("rod_area", 0.0, 0.0);
  s.gas_force = rig.number("gas_force", 0.0);

  TableReader driver(doc["driver"].as_table(), file, "driver");
  driver.only({"mode", "input", "gain", "kp", "ki", "voltage_limit"});
  const std::string mode = driver.text("mode", "current_source");
  if (mode == "current_source")
    s.driver_mode = lumped::DriverMode::current_source;
  else if (mode == "voltage")
    s.driver_mode = lumped::DriverMode::voltage;
  else if (mode == "current_pi")
    s.driver_mode = lumped::DriverMode::current_pi;
  else
    driver.fail("mode", "must be current_source, voltage or current_pi");
  s.voltage_column = driver.text("input", "command");
  if (s.voltage_column != "command" && s.voltage_column != "voltage")
    driver.fail("input", "must be \"command\" or \"voltage\"");
  s.driver.gain = driver.number("gain", 1.0);
  s.driver.kp = driver.number("kp", s.driver.kp, 0.0);
  s.driver.ki = driver.number("ki", s.driver.ki, 0.0);
  s.driver.voltage_limit = driver.positive("voltage_limit", s.driver.voltage_limit);

  TableReader coil(doc["coil"].as_table(), file, "coil");
  coil.only(
      {"resistance", "temperature_coefficient", "inductance", "flux_current", "flux_linkage"});
  s.coil.resistance_20c = coil.positive("resistance", s.coil.resistance_20c);
  // R(T) = R20 (1 + alpha (T - 20)) stays > 0 over the whole coil temperature domain.
  s.coil.temperature_coefficient =
      coil.within("temperature_coefficient", Domain::between(0.0, 0.0045, "1/K"),
                  lumped::kCopperAlpha, "copper 0.00393, aluminium 0.00403; R > 0 down to -200 C");
  s.coil.inductance = coil.number("inductance", 0.0, 0.0);
  s.coil.table_current = coil.numbers("flux_current");
  s.coil.table_flux = coil.numbers("flux_linkage");
  if (s.coil.table_current.size() != s.coil.table_flux.size() ||
      (!s.coil.table_current.empty() &&
       (s.coil.table_current.size() < 2 || s.coil.table_current.front() != 0.0)))
    coil.fail("flux_current", "and flux_linkage must have the same length >= 2, starting at 0 A");
  for (std::size_t k = 1; k < s.coil.table_current.size(); ++k)
    if (!(s.coil.table_current[k] > s.coil.table_current[k - 1]) ||
        !(s.coil.table_flux[k] > s.coil.table_flux[k - 1]))
      coil.fail("flux_linkage", "and flux_current must be strictly increasing");
  if (s.driver_mode == lumped::DriverMode::current_pi && s.coil.inductance <= 0 &&
      !s.coil.nonlinear() && !doc["effects"]["magnetic_hysteresis"])
    driver.fail("mode", "current_pi needs a coil inductance (or flux table / hysteresis)");

  TableReader valve(doc["valve"].as_table(), file, "valve");
  valve.only({"yield_current", "yield_pressure", "viscous_resistance", "yield_scale",
              "regularisation_flow", "case", "viscous_scale", "slit_fraction"});
  if (s.kind != lumped::RigKind::coil_bench && valve.has("case")) {
    // The valve's static map from the fluid chain of an FE case (path relative to this spec).
    const std::filesystem::path case_path =
        std::filesystem::path(file).parent_path() / valve.text("case", "");
    if (!std::filesystem::exists(case_path))
      valve.fail("case", "names no file: " + case_path.string());
    if (valve.has("yield_current") || valve.has("yield_pressure") ||
        valve.has("viscous_resistance"))
      valve.fail("case",
                 "replaces yield_current, yield_pressure and viscous_resistance: give "
                 "either the case or the table");
    if (valve.has("slit_fraction"))
      valve.fail(
          "slit_fraction",
          "shapes a table's Bingham line; a case's chain map is already its gap's exact law");
    s.valve.case_file = case_path.lexically_normal().string();
    s.valve.yield_scale = valve.number("yield_scale", 1.0, 0.0);
    s.valve.viscous_scale = valve.positive("viscous_scale", 1.0);
    s.valve.regularisation_flow =
        valve.positive("regularisation_flow", 1e-3 * s.piston_area * 1e-3);
  } else if (s.kind != lumped::RigKind::coil_bench) {
    s.valve.yield_current = valve.numbers("yield_current");
    s.valve.yield_pressure = valve.numbers("yield_pressure");
    if (s.valve.yield_current.empty() ||
        s.valve.yield_current.size() != s.valve.yield_pressure.size())
      valve.fail("yield_current", "and yield_pressure must be non-empty and of equal length");
    for (std::size_t k = 1; k < s.valve.yield_current.size(); ++k)
      if (!(s.valve.yield_current[k] > s.valve.yield_current[k - 1]))
        valve.fail("yield_current", "must be strictly increasing");
    s.valve.viscous_resistance = valve.positive("viscous_resistance", s.valve.viscous_resistance);
    s.valve.yield_scale = valve.number("yield_scale", 1.0, 0.0);
    s.valve.regularisation_flow =
        valve.positive("regularisation_flow", 1e-3 * s.piston_area * 1e-3);
    s.valve.slit_fraction = valve.within("slit_fraction", Domain::between(0.0, 1.0), 0.0,
                                         "0 the Bingham line, 1 the exact slit law");
  }

  TableReader effects(doc["effects"].as_table(), file, "effects");
  effects.only({"compressibility", "fluid_inertia", "magnetic_hysteresis", "eddy_currents",
                "coil_inductance", "coil_heating", "mr_response_time", "friction",
                "fluid_heating"});
  auto effect = [&](const std::string& name) {
    return TableReader(effects.sub(name), file, "effects." + name);
  };
  if (auto e = effect("compressibility"); effect_on(e)) {
    e.only({"enabled", "chamber_volume", "bulk_modulus", "air_volume", "air_process", "precharge"});
    lumped::ChamberBlock c;
    c.oil_volume = e.positive("chamber_volume", c.oil_volume);
    c.bulk_modulus = e.positive("bulk_modulus", c.bulk_modulus);
    c.air_volume = e.number("air_volume", 0.0, 0.0) / lumped::kRigChambers;  // total, split
    c.precharge = e.positive("precharge", c.precharge);
    const std::string process = e.text("air_process", "isothermal");
    if (process == "isothermal")
      c.polytropic = 1.0;
    else if (process == "adiabatic")
      c.polytropic = 1.4;
    else
      e.fail("air_process", "must be isothermal or adiabatic");
    s.compressibility = c;
  }
  if (auto e = effect("fluid_inertia"); effect_on(e)) {
    e.only({"enabled", "inertance"});
    s.inertance = e.positive("inertance", 1e8);
  }
  if (auto e = effect("magnetic_hysteresis"); effect_on(e)) {
    e.only({"enabled", "a", "b1", "b2", "d", "flux_per_ampere"});
    lumped::DuhemBlock h;
    h.a = e.number("a", h.a, 0.0);
    h.b1 = e.number("b1", h.b1, 0.0);
    h.b2 = e.positive("b2", h.b2);
    h.d = e.positive("d", h.d);
    h.flux_per_ampere = e.number("flux_per_ampere", h.b1 * h.b2 + h.d, 0.0);
    s.magnetic_hysteresis = h;
  }
  // The valve's own lag predicted from FE step responses: from [effects.eddy_currents] case, or
  // by default from the FE valve of [valve] case (the currents: `currents`, else the yield
  // table's currents > 0, else 1/4 .. 4/4 of the case's first circuit current).
  auto predicted = [&](const std::filesystem::path& case_path, const TableReader& e) {
    std::vector<double> currents =
        e.present() && e.has("currents") ? e.numbers("currents") : std::vector<double>{};
    if (currents.empty())
      for (double i : s.valve.yield_current)
        if (i > 0.0) currents.push_back(i);
    if (currents.empty()) {
      const double i = std::abs(cases::load_case(case_path).problem.circuits.at(0).current);
      for (int k = 1; k <= 4; ++k) currents.push_back(0.25 * k * (i > 0.0 ? i : 1.0));
    }
    return predict_field_lag(case_path, currents);
  };
  const auto eddy_table = effect("eddy_currents");
  if (!eddy_table.present() && !s.valve.case_file.empty() &&
      s.kind != lumped::RigKind::coil_bench) {
    s.predicted_eddy_lag = predicted(s.valve.case_file, eddy_table);
  } else if (auto e = eddy_table; effect_on(e)) {
    e.only({"enabled", "time_constant", "relative_permeability", "conductivity", "core_radius",
            "case", "currents"});
    if (e.has("case")) {
      const std::filesystem::path case_path =
          std::filesystem::path(file).parent_path() / e.text("case", "");
      if (!std::filesystem::exists(case_path))
        e.fail("case", "names no file: " + case_path.string());
      s.predicted_eddy_lag = predicted(case_path.lexically_normal(), e);
    } else if (e.has("time_constant")) {
      s.eddy_time_constant = e.positive("time_constant", 0.01);
    } else {
      s.eddy_time_constant = lumped::eddy_time_constant(e.positive("relative_permeability", 1000.0),
                                                        e.positive("conductivity", 5e6),
                                                        e.positive("core_radius", 0.01));
    }
  }
  if (auto e = effect("coil_inductance"); effect_on(e)) {
    e.only({"enabled", "inductance"});
    s.coil.inductance = e.positive("inductance", 0.1);
    if (s.driver_mode == lumped::DriverMode::current_source)
      e.fail("enabled", "needs a voltage or current_pi driver (a current source imposes i)");
  }
  if (auto e = effect("coil_heating"); effect_on(e)) {
    e.only({"enabled", "thermal_resistance", "thermal_time_constant", "ambient"});
    lumped::ThermalBlock th;
    th.thermal_resistance = e.positive("thermal_resistance", th.thermal_resistance);
    th.thermal_time_constant = e.positive("thermal_time_constant", th.thermal_time_constant);
    th.ambient_c = e.within("ambient", valve::kCoilTemperature, 20.0,
                            "where the linear resistivity of copper holds");
    s.coil_heating = th;
  }
  if (auto e = effect("fluid_heating"); effect_on(e)) {
    e.only({"enabled", "thermal_resistance", "thermal_time_constant", "viscosity_slope"});
    lumped::FluidHeatingBlock h;
    h.thermal_resistance = e.positive("thermal_resistance", h.thermal_resistance);
    h.thermal_time_constant = e.positive("thermal_time_constant", h.thermal_time_constant);
    h.viscosity_slope = e.number("viscosity_slope", h.viscosity_slope, 0.0);
    if (s.kind == lumped::RigKind::coil_bench)
      e.fail("enabled", "fluid_heating needs a rig with a valve (not a coil_bench)");
    s.fluid_heating = h;
  }
  if (auto e = effect("mr_response_time"); effect_on(e)) {
    e.only({"enabled", "time_constant"});
    s.mr_response_time = e.positive("time_constant", 0.005);
  }
  if (auto e = effect("friction"); effect_on(e)) {
    e.only({"enabled", "coulomb_force", "velocity_scale"});
    s.coulomb_force = e.number("coulomb_force", 50.0, 0.0);
    s.friction_velocity = e.positive("velocity_scale", 1e-3);
    if (s.kind != lumped::RigKind::damper)
      e.fail("enabled", "friction needs rig kind = \"damper\"");
  }
  return s;
}

PhenoSpec read_pheno(const TableReader& model, lumped::PhenoKind kind) {
  model.only({"kind", "field", "motion_scale", "regularisation", "params", "orientation"});
  PhenoSpec p;
  p.setup.kind = kind;
  p.setup.motion_column = "velocity";
  p.setup.position_column = "displacement";
  p.setup.output_column = "force";
  p.setup.field_column = model.text("field", "current");
  if (p.setup.field_column == "none")
    p.setup.field_column.clear();
  else if (p.setup.field_column != "current" && p.setup.field_column != "command")
    model.fail("field", "must be \"current\", \"command\" or \"none\"");
  p.setup.orientation = model.number("orientation", 1.0);
  p.setup.settings.motion_scale = model.positive("motion_scale", 0.05);
  p.setup.settings.eps = model.positive("regularisation", 1e-5);
  TableReader params(model.sub("params"), model.file(), "model.params");
  if (!params.present()) model.fail("params", "is required");
  std::set<std::string> names;
  for (const auto& spec : lumped::pheno_params(kind)) {
    names.insert(spec.name);
    if (!params.has(spec.name) && !spec.optional)  // an optional one is 0 (absent) by default
      params.fail(spec.name, "is required (" + spec.unit + ")");
    p.params.push_back(params.number(spec.name, 0.0));
  }
  params.only(names);
  return p;
}

}  // namespace

SimulationSpec read_simulation_spec(const std::string& path) {
  if (!std::filesystem::exists(path)) throw InputError(path + ": spec not found");
  const std::string text = read_input_file(path);
  toml::table doc;
  try {
    doc = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    std::ostringstream msg;
    msg << path << ":" << e.source().begin.line << ": " << e.description();
    throw InputError(msg.str());
  }
  for (const auto& [k, v] : doc) {
    static const std::set<std::string> tables = {"rig",     "driver", "coil",        "valve",
                                                 "effects", "model",  "sensor_noise"};
    if (!tables.count(std::string(k.str())))
      throw InputError(path + ": unknown table [" + std::string(k.str()) +
                       "] (expected rig, driver, coil, valve, effects, model, sensor_noise)");
  }
  SimulationSpec spec;
  spec.path = path;
  TableReader model(doc["model"].as_table(), path, "model");
  if (model.present()) {
    const std::string kind = model.text("kind", "");
    lumped::PhenoKind pk;
    if (kind == "tf14") {
      model.only({"kind"});
      spec.tf14 = true;
    } else if (kind == "lugre-paper001") {
      model.only({"kind", "piston_area"});
      spec.lugre_paper001 = true;
      spec.piston_area = model.positive("piston_area", spec.piston_area);
    } else if (lumped::parse_pheno_kind(kind, pk)) {
      spec.pheno = read_pheno(model, pk);
    } else {
      model.fail("kind", "must be tf14, lugre-paper001, bingham, lugre, bouc-wen, maxwell or dahl");
    }
  } else {
    spec.rig = read_rig(doc, path);
  }
  TableReader noise(doc["sensor_noise"].as_table(), path, "sensor_noise");
  if (noise.present()) {
    for (const auto& [k, v] : *doc["sensor_noise"].as_table()) {
      std::string key(k.str());
      if (key == "seed") {
        auto seed = v.value<int64_t>();
        if (!seed || *seed < 0) noise.fail("seed", "must be a non-negative integer");
        spec.noise_seed = static_cast<unsigned>(*seed);
      } else {
        spec.sensor_noise[key] = noise.number(key, 0.0, 0.0);
      }
    }
  }
  if (spec.rig) {
    spec.rig->sensor_noise = spec.sensor_noise;
    spec.rig->noise_seed = spec.noise_seed;
  }
  return spec;
}

std::vector<std::string> spec_drive_columns(const SimulationSpec& spec) {
  if (spec.rig) return lumped::rig_drive_columns(*spec.rig);
  if (spec.tf14) return {"current"};
  if (spec.lugre_paper001) return {"velocity", "current"};
  std::vector<std::string> cols = {"displacement", "velocity"};
  if (!spec.pheno->setup.field_column.empty()) cols.push_back(spec.pheno->setup.field_column);
  return cols;
}

lumped::Recording simulate_spec(const SimulationSpec& spec, const lumped::Recording& drive) {
  for (const auto& c : spec_drive_columns(spec))
    if (!drive.columns.count(c))
      throw InputError(spec.path + ": the model is driven by '" + c + "', which the input (" +
                       (drive.csv_path.empty() ? std::string("--signal") : drive.csv_path) +
                       ") does not have");
  if (spec.rig) return lumped::simulate_rig(with_chain_map(*spec.rig, drive), drive);
  lumped::Recording rec;
  rec.t = drive.t;
  for (const auto& c : spec_drive_columns(spec)) rec.columns[c] = drive.column(c);
  if (spec.tf14) {
    std::vector<double> p = lumped::simulate_transfer_function(lumped::tf14_paper000(), drive.t,
                                                               drive.column("current"));
    for (double& v : p) v *= 1e5;  // bar -> Pa
    rec.columns["pressure"] = p;
    rec.meta.output = "pressure";
    rec.meta.rig.kind = lumped::RigKind::constant_velocity_pump;
    rec.meta.description = "TF14 of paper 000 (Table 7), current -> pressure";
  } else if (spec.lugre_paper001) {
    std::vector<double> flow = drive.column("velocity");
    for (double& q : flow) q *= spec.piston_area;
    rec.columns["flow"] = flow;
    if (drive.columns.count("displacement"))
      rec.columns["displacement"] = drive.column("displacement");
    rec.columns["pressure"] =
        lumped::simulate_lugre_paper001(drive.t, flow, drive.column("current"));
    rec.meta.output = "pressure";
    rec.meta.rig.kind = lumped::RigKind::bypass_cylinder;
    rec.meta.rig.piston_area = spec.piston_area;
    rec.meta.description = "LuGre valve model of paper 001 (eqs. 8-9, Table 3)";
  } else {
    lumped::Recording driven =
        drive;  // the model reads its output column only for scales: give zeros
    driven.columns["force"] = std::vector<double>(drive.t.size(), 0.0);
    rec.columns["force"] = lumped::simulate_pheno(driven, spec.pheno->setup, spec.pheno->params);
    rec.meta.output = "force";
    rec.meta.rig.kind = lumped::RigKind::damper;
    rec.meta.description = lumped::pheno_name(spec.pheno->setup.kind) + " model";
  }
  rec.meta.drive = spec_drive_columns(spec);
  std::mt19937 rng(spec.noise_seed);
  for (const auto& [column, sigma] : spec.sensor_noise) {
    auto it = rec.columns.find(column);
    if (it == rec.columns.end())
      throw InputError(spec.path + ": [sensor_noise] " + column +
                       " is not a column this model writes");
    std::normal_distribution<double> noise(0.0, sigma);
    for (double& v : it->second) v += noise(rng);
  }
  return rec;
}

}  // namespace rheomag::coupling
