// Writing and reading the fitted-model JSON (see fit_model_json.hpp); running a model read back
// is in fit_model_run.cpp, so this reader links without the fitting code (its fuzz test does).

#include "identify/fit_model_json.hpp"
#include "core/input_file.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <sstream>

#include "core/error.hpp"
#include "core/quantity_domain.hpp"

namespace rheomag::identify {

namespace {

using json = nlohmann::json;

/// The keys every fitted-model document shares: format, kind, model, rig, drive, output.
json common_json(const std::string& kind, const std::string& model,
                 const lumped::RecordingMeta& meta) {
  json j;
  j["format"] = kFitModelFormat;
  j["kind"] = kind;
  j["model"] = model;
  j["rig"] =
      meta.rig.kind ? json(std::string(lumped::kRigKindNames.name(*meta.rig.kind))) : json(nullptr);
  j["drive"] = meta.drive;
  j["output"] = meta.output;
  return j;
}

/// Parameters as an ordered array (the order a model's parameter vector has) and, for people and
/// existing scripts, the name -> value and name -> standard error objects.
void put_parameters(json& j, const std::vector<FittedParameter>& params) {
  j["parameters"] = json::array();
  j["params"] = json::object();
  j["standard_errors"] = json::object();
  for (const FittedParameter& p : params) {
    const json se = p.standard_error && std::isfinite(*p.standard_error) ? json(*p.standard_error)
                                                                         : json(nullptr);
    json entry = {{"name", p.name},
                  {"unit", p.unit},
                  {"value", p.value},
                  {"standard_error", se},
                  {"fixed", p.fixed}};
    if (p.standard_error_between_recordings && std::isfinite(*p.standard_error_between_recordings))
      entry["standard_error_between_recordings"] = *p.standard_error_between_recordings;
    if (!p.held_because.empty()) entry["held_because"] = p.held_because;
    j["parameters"].push_back(entry);
    j["params"][p.name] = p.value;
    j["standard_errors"][p.name] = se;
  }
}

/// A checked view of one JSON value at a key path, for messages "file: key 'a.b': ...".
class Field {
 public:
  Field(const json& value, std::string file, std::string path)
      : value_(&value), file_(std::move(file)), path_(std::move(path)) {}

  [[noreturn]] void fail(const std::string& message) const {
    throw InputError(file_ + ": key '" + path_ + "': " + message);
  }
  Field at(const std::string& key) const {
    if (!value_->is_object()) fail("expected an object, got " + type());
    const auto it = value_->find(key);
    const std::string path = path_.empty() ? key : path_ + "." + key;
    if (it == value_->end()) throw InputError(file_ + ": key '" + path + "' is missing");
    return Field(*it, file_, path);
  }
  void require_object() const {
    if (!value_->is_object()) fail("expected an object, got " + type());
  }
  bool has(const std::string& key) const {
    return value_->is_object() && value_->contains(key) && !(*value_)[key].is_null();
  }
  Field operator[](std::size_t k) const {
    return Field((*value_)[k], file_, path_ + "[" + std::to_string(k) + "]");
  }
  std::size_t size(std::size_t at_least = 0) const {
    if (!value_->is_array()) fail("expected an array, got " + type());
    if (value_->size() < at_least)
      fail("expected at least " + std::to_string(at_least) + " entries, got " +
           std::to_string(value_->size()));
    return value_->size();
  }
  std::string text() const {
    if (!value_->is_string()) fail("expected a string, got " + type());
    return value_->get<std::string>();
  }
  bool flag() const {
    if (!value_->is_boolean()) fail("expected true or false, got " + type());
    return value_->get<bool>();
  }
  double number(const Domain& domain = Domain::finite()) const {
    if (!value_->is_number()) fail("expected " + domain.describe() + ", got " + type());
    const double v = value_->get<double>();
    const std::string why = domain.violation(v);
    if (!why.empty()) fail(why);
    return v;
  }
  std::vector<double> numbers(std::size_t at_least, const Domain& domain) const {
    std::vector<double> out(size(at_least));
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = (*this)[k].number(domain);
    return out;
  }
  std::vector<std::string> texts() const {
    std::vector<std::string> out(size());
    for (std::size_t k = 0; k < out.size(); ++k) out[k] = (*this)[k].text();
    return out;
  }
  /// One of `choices` (messages list them).
  std::string one_of(const std::vector<std::string>& choices) const {
    const std::string t = text();
    if (std::find(choices.begin(), choices.end(), t) != choices.end()) return t;
    std::string list;
    for (const std::string& c : choices) list += (list.empty() ? "\"" : ", \"") + c + "\"";
    fail("expected one of " + list + ", got \"" + t + "\"");
  }

 private:
  std::string type() const {
    if (value_->is_number()) return "a number (" + value_->dump() + ")";
    if (value_->is_string()) return "a string (" + value_->dump() + ")";
    return std::string(value_->type_name());
  }
  const json* value_;
  std::string file_, path_;
};

std::vector<FittedParameter> read_parameters(const Field& list) {
  std::vector<FittedParameter> params(list.size(1));
  for (std::size_t k = 0; k < params.size(); ++k) {
    const Field p = list[k];
    params[k].name = p.at("name").text();
    params[k].unit = p.at("unit").text();
    params[k].value = p.at("value").number();
    if (p.has("standard_error"))
      params[k].standard_error = p.at("standard_error").number(Domain::non_negative());
    if (p.has("standard_error_between_recordings"))
      params[k].standard_error_between_recordings =
          p.at("standard_error_between_recordings").number(Domain::non_negative());
    params[k].fixed = p.at("fixed").flag();
  }
  return params;
}

/// "" if `value` is in `domain` up to the rounding of a fit that ended on a bound (the solver works
/// on scaled parameters: 0.25 comes back as 0.25000000000000006), else the domain's violation.
std::string outside_fit_bounds(const Domain& domain, double value) {
  Domain rounded = domain;
  rounded.lower -= 1e-9 * std::abs(domain.lower);
  rounded.upper += 1e-9 * std::abs(domain.upper);
  return rounded.contains(value) ? std::string() : domain.violation(value);
}

/// Strictly increasing values (the grid of a static map).
void require_increasing(const Field& f, const std::vector<double>& v) {
  for (std::size_t k = 1; k < v.size(); ++k)
    if (!(v[k] > v[k - 1]))
      f[k].fail("expected a value above the previous one (" + std::to_string(v[k - 1]) +
                "): the grid must increase strictly");
}

GreyboxFit read_greybox(const Field& root, const std::string& model) {
  GreyboxFit fit;
  fit.model = model;
  lumped::parse_pheno_kind(model, fit.setup.kind);
  const Field setup = root.at("setup");
  fit.setup.motion_column = setup.at("motion_column").one_of({"velocity", "flow"});
  fit.setup.position_column = setup.at("position_column").text();
  fit.setup.field_column = setup.at("field_column").text();
  fit.setup.output_column = root.at("output").one_of({"force", "pressure"});
  fit.setup.orientation = setup.at("orientation").number(Domain::between(-1.0, 1.0));
  if (std::abs(fit.setup.orientation) != 1.0)
    setup.at("orientation").fail("expected 1 or -1, got " + std::to_string(fit.setup.orientation));
  // The motion sensor's lag (absent in files written before it, or 0: the drives as recorded).
  if (setup.has("motion_lead_s"))
    fit.setup.motion_lead = setup.at("motion_lead_s").number(Domain::between(-1.0, 1.0, "s"));
  const Field s = setup.at("settings");
  fit.setup.settings.eps = s.at("eps").number(Domain::positive());
  fit.setup.settings.motion_scale = s.at("motion_scale").number(Domain::positive());
  fit.setup.settings.position_scale = s.at("position_scale").number(Domain::positive());
  fit.setup.settings.output_scale = s.at("output_scale").number(Domain::non_negative());
  // The highest fitted field level (damper; absent in files written before it: no limit).
  if (s.has("field_high")) fit.setup.settings.field_high = s.at("field_high").number();
  // The offset's level at rest for tared recordings (absent in files written before it, or where
  // no training recording was tared: the offset does not reach a tared output).
  if (s.has("rest_reference")) fit.setup.settings.rest_reference = s.at("rest_reference").number();
  const Field list = root.at("parameters");
  fit.params = read_parameters(list);
  const std::vector<lumped::PhenoParam>& expected = lumped::pheno_params(fit.setup.kind);
  // Parameters added to a model after files were written (PhenoParam::optional), whose value 0 is
  // the model without them: a file written before them reads as the model it was fitted as.
  for (std::size_t k = 0; k < expected.size(); ++k)
    if (expected[k].optional &&
        std::none_of(fit.params.begin(), fit.params.end(),
                     [&](const FittedParameter& p) { return p.name == expected[k].name; })) {
      FittedParameter none;
      none.name = expected[k].name;
      none.unit = expected[k].unit;
      none.fixed = true;
      fit.params.insert(
          fit.params.begin() + static_cast<std::ptrdiff_t>(std::min(k, fit.params.size())), none);
    }
  if (fit.params.size() != expected.size())
    list.fail("model " + model + " has " + std::to_string(expected.size()) + " parameters, got " +
              std::to_string(fit.params.size()));
  for (std::size_t k = 0; k < expected.size(); ++k)
    if (fit.params[k].name != expected[k].name)
      list[k].at("name").fail("expected \"" + expected[k].name + "\" (parameter " +
                              std::to_string(k + 1) + " of " + model + "), got \"" +
                              fit.params[k].name + "\"");
  // Each value in its physical domain (the fit's own bounds where they do not scale with the data):
  // a negative viscosity or transition would be simulated, not refused, further on.
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const std::string why =
        outside_fit_bounds(lumped::pheno_param_domain(fit.setup.kind, k), fit.params[k].value);
    if (why.empty()) continue;
    for (std::size_t j = 0; j < list.size(); ++j)
      if (list[j].at("name").text() == expected[k].name)
        list[j].at("value").fail("parameter " + expected[k].name + " of " + model + ": " + why +
                                 " (the bound a fit of " + model + " keeps it in)");
  }
  return fit;
}

ValveChainFit read_valve_chain(const Field& root) {
  ValveChainFit fit;
  const Field setup = root.at("setup");
  fit.setup.motion_column = setup.at("motion_column").one_of({"velocity", "flow"});
  fit.setup.field_column = setup.at("field_column").one_of({"current", "current_cmd"});
  fit.setup.output_column = root.at("output").one_of({"force", "pressure"});
  fit.setup.piston_area = setup.at("piston_area").number(Domain::non_negative("m^2"));
  fit.setup.gas_force = setup.at("gas_force").number(Domain::finite("N"));
  fit.setup.compliant = setup.at("compliant").flag();
  fit.setup.eps_flow = setup.at("eps_flow").number(Domain::positive("m^3/s"));
  if (fit.setup.motion_column == "velocity" && fit.setup.piston_area <= 0.0)
    setup.at("piston_area").fail("expected a positive number (m^2) for a velocity drive, got 0");
  const Field map = root.at("static_map");
  auto table = std::make_shared<lumped::ChainMapTable>();
  table->case_file = map.at("case_file").text();
  const Field current = map.at("current"), flow = map.at("flow"), yield = map.at("yield");
  table->current = current.numbers(2, Domain::non_negative("A"));
  require_increasing(current, table->current);
  if (table->current.front() != 0.0) current[0].fail("expected 0 (the grid starts at no current)");
  table->flow = flow.numbers(2, Domain::positive("m^3/s"));
  require_increasing(flow, table->flow);
  table->yield = yield.numbers(0, Domain::non_negative("Pa"));
  if (table->yield.size() != table->current.size() * table->flow.size())
    yield.fail("expected " + std::to_string(table->current.size() * table->flow.size()) +
               " values (current x flow), got " + std::to_string(table->yield.size()));
  table->viscous_resistance = map.at("viscous_resistance").number(Domain::non_negative("Pa s/m^3"));
  fit.setup.map = std::move(table);
  const Field list = root.at("parameters");
  fit.params = read_parameters(list);
  if (fit.params.size() != 4)
    list.fail("model valve-chain has 4 parameters, got " + std::to_string(fit.params.size()));
  // The fit's bounds (identify/valve_chain_fit.cpp), by position as the fit writes them.
  static const std::array<std::pair<const char*, Domain>, 4> bounds = {
      {{"yield_scale", Domain::between(1e-2, 1e2)},
       {"viscous_scale", Domain::between(1e-2, 1e3)},
       {"field_time_constant", Domain::between(1e-4, 10.0, "s")},
       {"hydraulic_capacitance", Domain::non_negative("m^3/Pa")}}};
  for (std::size_t k = 0; k < bounds.size(); ++k) {
    if (fit.params[k].name != bounds[k].first)
      list[k].at("name").fail("expected \"" + std::string(bounds[k].first) + "\" (parameter " +
                              std::to_string(k + 1) + " of valve-chain), got \"" +
                              fit.params[k].name + "\"");
    const std::string why = outside_fit_bounds(bounds[k].second, fit.params[k].value);
    if (!why.empty())
      list[k].at("value").fail("parameter " + fit.params[k].name + " of valve-chain: " + why +
                               " (the bound a fit of valve-chain keeps it in)");
  }
  return fit;
}

/// The optional "operating_range" object: each quantity present has its column, low <= high.
OperatingRange read_operating_range(const Field& range) {
  const auto extent = [&range](const char* key) -> std::optional<DriveExtent> {
    if (!range.has(key)) return std::nullopt;
    const Field e = range.at(key);
    DriveExtent x{e.at("column").text(), e.at("low").number(), e.at("high").number()};
    if (x.high < x.low)
      e.at("high").fail("expected a value at least 'low' (" + std::to_string(x.low) + ")");
    return x;
  };
  range.require_object();
  return {extent("field"), extent("speed"), extent("stroke")};
}

}  // namespace

json fit_model_json(const GreyboxFit& fit, const lumped::RecordingMeta& meta) {
  json j = common_json("grey-box", fit.model, meta);
  j["setup"] = {{"motion_column", fit.setup.motion_column},
                {"position_column", fit.setup.position_column},
                {"field_column", fit.setup.field_column},
                {"orientation", fit.setup.orientation},
                {"settings",
                 {{"eps", fit.setup.settings.eps},
                  {"motion_scale", fit.setup.settings.motion_scale},
                  {"position_scale", fit.setup.settings.position_scale},
                  {"output_scale", fit.setup.settings.output_scale}}}};
  if (fit.setup.motion_lead != 0.0) j["setup"]["motion_lead_s"] = fit.setup.motion_lead;
  if (std::isfinite(fit.setup.settings.field_high))
    j["setup"]["settings"]["field_high"] = fit.setup.settings.field_high;
  if (std::isfinite(fit.setup.settings.rest_reference))
    j["setup"]["settings"]["rest_reference"] = fit.setup.settings.rest_reference;
  put_parameters(j, fit.params);
  if (fit.inertance_gain) {
    const int k = lumped::pheno_param_index(fit.setup.kind, "inertance");
    j["inertance_check"] = {{"gain_percent", 100.0 * *fit.inertance_gain},
                            {"held", fit.params.at(static_cast<std::size_t>(k)).fixed}};
  }
  return j;
}

json fit_model_json(const ValveChainFit& fit, const lumped::RecordingMeta& meta) {
  json j = common_json("valve-chain", fit.model, meta);
  j["setup"] = {
      {"motion_column", fit.setup.motion_column}, {"field_column", fit.setup.field_column},
      {"piston_area", fit.setup.piston_area},     {"gas_force", fit.setup.gas_force},
      {"compliant", fit.setup.compliant},         {"eps_flow", fit.setup.eps_flow}};
  const lumped::ChainMapTable& m = *fit.setup.map;
  j["static_map"] = {
      {"case_file", m.case_file},
      {"current", m.current},
      {"flow", m.flow},
      {"yield", m.yield},
      {"viscous_resistance", m.viscous_resistance},
      {"units",
       {{"current", "A"}, {"flow", "m^3/s"}, {"yield", "Pa"}, {"viscous_resistance", "Pa s/m^3"}}}};
  put_parameters(j, fit.params);
  return j;
}

json black_box_model_json(const std::string& name,
                          const std::vector<std::pair<std::string, double>>& params,
                          const lumped::RecordingMeta& meta) {
  json j = common_json("black-box", name, meta);
  j["params"] = json::object();
  for (const auto& [key, value] : params) j["params"][key] = value;
  return j;
}

FitModel parse_fit_model_json(std::string_view text, const std::string& file) {
  json doc;
  try {
    doc = json::parse(text);
  } catch (const json::parse_error& e) {
    throw InputError(file + ": not a JSON document (byte " + std::to_string(e.byte) +
                     "); expected the output of 'rheomag fit --json' or 'fit-family --json'");
  } catch (const json::exception& e) {  // e.g. a number beyond the range of a double
    const std::string what = e.what();
    const std::size_t cut = what.find("] ");
    throw InputError(file + ": not a readable JSON document: " +
                     (cut == std::string::npos ? what : what.substr(cut + 2)));
  }
  const Field root(doc, file, "");
  if (!doc.is_object())
    throw InputError(file + ": expected a JSON object (the output of 'rheomag fit --json')");
  const std::string format = root.at("format").text();
  if (format != kFitModelFormat)
    root.at("format").fail("expected \"" + std::string(kFitModelFormat) + "\", got \"" + format +
                           "\"");
  FitModel m;
  const std::string kind = root.at("kind").one_of({"grey-box", "valve-chain", "black-box"});
  m.model = root.at("model").text();
  if (kind == "black-box")
    root.at("kind").fail("model '" + m.model +
                         "' is a black-box model: its JSON lists its parameters for reading, "
                         "but only grey-box and valve-chain models can be read back and run");
  if (root.has("rig"))
    m.rig = lumped::kRigKindNames.parse(root.at("rig").text(), file + ": key 'rig'");
  m.drive = root.at("drive").texts();
  if (m.drive.empty()) root.at("drive").fail("expected at least one drive column, got none");
  m.output = root.at("output").text();
  if (kind == "valve-chain") {
    if (m.model != "valve-chain")
      root.at("model").fail("expected \"valve-chain\", got \"" + m.model + "\"");
    m.valve_chain = read_valve_chain(root);
  } else {
    lumped::PhenoKind k;
    if (!lumped::parse_pheno_kind(m.model, k)) {
      std::string names;
      for (int k = 0; k <= static_cast<int>(lumped::PhenoKind::damper); ++k)
        names +=
            (names.empty() ? "" : ", ") + lumped::pheno_name(static_cast<lumped::PhenoKind>(k));
      root.at("model").fail("expected a grey-box model (" + names + "), got \"" + m.model + "\"");
    }
    m.greybox = read_greybox(root, m.model);
  }
  if (root.has("operating_range"))
    m.operating_range = read_operating_range(root.at("operating_range"));
  return m;
}

FitModel read_fit_model_json(const std::filesystem::path& path) {
  return parse_fit_model_json(read_input_file(path), path.string());
}

}  // namespace rheomag::identify
