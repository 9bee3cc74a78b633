// Reader of the [rheology] table of a materials TOML file; the format is in docs/fluid.md.

#include "fluid/fluid.hpp"
#include "core/input_file.hpp"

#include <toml++/toml.h>
#include <cmath>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/error.hpp"

namespace rheomag::fluid {

namespace {

/// Error text "ORIGIN: [rheology].KEY (line N): WHAT".
std::string where(const std::string& origin, const std::string& key, const toml::node* node) {
  std::string text = origin + ": [rheology]." + key;
  if (node && node->source().begin.line > 0)
    text += " (line " + std::to_string(node->source().begin.line) + ")";
  return text;
}

double positive(const toml::table& table, const std::string& key, const std::string& origin,
                const std::string& prefix, bool required, double fallback) {
  const toml::node* node = table.get(key);
  if (!node) {
    if (required) throw InputError(origin + ": missing key [rheology]." + prefix + key);
    return fallback;
  }
  auto value = node->value<double>();
  if (!value || !std::isfinite(*value) || !(*value > 0.0))
    throw InputError(where(origin, prefix + key, node) + ": expected a number > 0");
  return *value;
}

std::vector<double> numbers(const toml::table& table, const std::string& key,
                            const std::string& origin, const std::string& prefix) {
  const toml::node* node = table.get(key);
  if (!node) throw InputError(origin + ": missing key [rheology]." + prefix + key);
  const toml::array* array = node->as_array();
  if (!array)
    throw InputError(where(origin, prefix + key, node) + ": expected an array of numbers");
  std::vector<double> out;
  for (const auto& item : *array) {
    auto value = item.value<double>();
    if (!value) throw InputError(where(origin, prefix + key, &item) + ": expected a number");
    out.push_back(*value);
  }
  return out;
}

YieldStressCurve parse_yield_stress(const toml::table& rheology, const std::string& origin) {
  const double scale = rheology.get("yield_stress_scale")
                           ? positive(rheology, "yield_stress_scale", origin, "", true, 1.0)
                           : 1.0;
  const toml::node* node = rheology.get("yield_stress");
  if (!node) return YieldStressCurve(NoYieldStress{}, scale);
  if (const toml::array* pairs = node->as_array()) {
    // yield_stress = [[B (T), tau_y (Pa)], ...], the form used by cases/materials/*.toml.
    std::vector<double> b, tau;
    for (const auto& item : *pairs) {
      const toml::array* pair = item.as_array();
      auto x = pair && pair->size() == 2 ? (*pair)[0].value<double>() : std::nullopt;
      auto y = pair && pair->size() == 2 ? (*pair)[1].value<double>() : std::nullopt;
      if (!x || !y)
        throw InputError(where(origin, "yield_stress", &item) +
                         ": expected [B (T), yield stress (Pa)] pairs of numbers");
      b.push_back(*x);
      tau.push_back(*y);
    }
    try {
      return YieldStressCurve(YieldStressTable(std::move(b), std::move(tau)), scale);
    } catch (const InputError& e) {
      throw InputError(where(origin, "yield_stress", node) + ": " + e.what());
    }
  }
  const toml::table* table = node->as_table();
  if (!table)
    throw InputError(where(origin, "yield_stress", node) +
                     ": expected [[B, tau], ...] pairs or a table with key model = "
                     "\"table\"|\"polynomial\"|\"carlson\"|\"none\"");
  const std::string prefix = "yield_stress.";
  auto model = table->get("model") ? table->get("model")->value<std::string>() : std::nullopt;
  if (!model)
    throw InputError(origin + ": [rheology.yield_stress] needs model = \"table\", " +
                     "\"polynomial\", \"carlson\" or \"none\"");
  try {
    if (*model == "table")
      return YieldStressCurve(YieldStressTable(numbers(*table, "b", origin, prefix),
                                               numbers(*table, "tau", origin, prefix)),
                              scale);
    if (*model == "polynomial") {
      double b_max =
          positive(*table, "b_max", origin, prefix, false, std::numeric_limits<double>::infinity());
      return YieldStressCurve(
          YieldStressPolynomial(numbers(*table, "coefficients", origin, prefix), b_max), scale);
    }
    if (*model == "carlson") {
      double phi = positive(*table, "volume_fraction", origin, prefix, true, 0.0);
      double c = positive(*table, "carrier_factor", origin, prefix, false, 1.0);
      return YieldStressCurve(CarlsonYieldStress(phi, c), scale);
    }
    if (*model == "none") return YieldStressCurve(NoYieldStress{}, scale);
  } catch (const InputError& e) {
    throw InputError(origin + ": [rheology.yield_stress]: " + e.what());
  }
  throw InputError(where(origin, "yield_stress.model", table->get("model")) + ": unknown model \"" +
                   *model + "\"; expected \"table\", \"polynomial\", \"carlson\" or \"none\"");
}

/// A finite number of [rheology] (`fallback` when absent) in `domain`; InputError naming the key.
double number_in(const toml::table& table, const std::string& key, const std::string& origin,
                 const Domain& domain, double fallback) {
  const toml::node* node = table.get(key);
  if (!node) return fallback;
  const std::optional<double> value = node->value<double>();
  if (!value) throw InputError(where(origin, key, node) + ": expected " + domain.describe());
  const std::string problem = domain.violation(*value);
  if (!problem.empty()) throw InputError(where(origin, key, node) + ": " + problem);
  return *value;
}

FluidTemperatureLaw parse_temperature_law(const toml::table& rheology, const std::string& origin) {
  FluidTemperatureLaw law;
  law.reference = number_in(rheology, "temperature", origin, kFluidTemperature, law.reference);
  law.activation_temperature = number_in(rheology, "viscosity_activation_temperature", origin,
                                         Domain::non_negative("K"), 0.0);
  law.yield_stress_coefficient = number_in(rheology, "yield_stress_temperature_coefficient", origin,
                                           Domain::between(-0.02, 0.02, "1/K"), 0.0);
  return law;
}

}  // namespace

Fluid parse_fluid(std::string_view toml_text, const std::string& origin) {
  toml::table document;
  try {
    document = toml::parse(toml_text, origin);
  } catch (const toml::parse_error& e) {
    throw InputError(origin + " (line " + std::to_string(e.source().begin.line) +
                     "): TOML syntax error: " + std::string(e.description()));
  }
  const toml::table* rheology = document["rheology"].as_table();
  if (!rheology) throw InputError(origin + ": missing table [rheology]");
  Fluid fluid;
  fluid.name = document["material"]["name"].value_or(document["name"].value_or(std::string{}));
  if (fluid.name.empty())
    fluid.name = (*rheology)["name"].value_or(std::filesystem::path(origin).stem().string());
  fluid.viscosity = positive(*rheology, "viscosity", origin, "", true, 0.0);
  fluid.density = positive(*rheology, "density", origin, "", true, 0.0);
  fluid.flow_index = positive(*rheology, "flow_index", origin, "", false, 1.0);
  if (fluid.flow_index > 3.0 || fluid.flow_index < 0.1)
    throw InputError(where(origin, "flow_index", rheology->get("flow_index")) +
                     ": expected a Herschel-Bulkley exponent in [0.1, 3]");
  fluid.source = (*rheology)["source"].value_or(
      document["material"]["source"].value_or(document["source"].value_or(std::string{})));
  fluid.yield_stress = parse_yield_stress(*rheology, origin);
  fluid.temperature = parse_temperature_law(*rheology, origin);
  return fluid;
}

Fluid read_fluid(const std::filesystem::path& file) {
  return parse_fluid(read_input_file(file), file.string());
}

}  // namespace rheomag::fluid
