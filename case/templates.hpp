#pragma once
// Parametric valve templates: named dimensions, coil and materials -> region outlines.

#include <cmath>
#include <functional>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "case/region_outline.hpp"

namespace rheomag::cases {

/// What a template parameter holds.
enum class ParameterKind {
  length,    ///< a length (file units in the case, metres inside), > 0
  count,     ///< a pure number such as coil turns, > 0
  material,  ///< a material name
  name,      ///< a plain name (e.g. the coil's circuit)
};

/// What a template parameter stands for in the design (beyond its kind).
enum class ParameterRole {
  dimension,  ///< a length of the geometry
  wall,       ///< a steel wall thickness (the min_wall quantity takes the thinnest)
  count,      ///< a count (coil turns)
  choice,     ///< a material or name
  fluid,      ///< the MR fluid of the gaps: a material with a [rheology] table
};

/// One named parameter of a template: key, unit, default, range, role and meaning.
struct TemplateParameter {
  std::string key;
  ParameterKind kind = ParameterKind::length;
  double default_number = 0.0;  ///< length defaults in metres
  std::string default_text;     ///< material / name defaults
  std::string doc;              ///< one line: what it is (and why the default)
  ParameterRole role = ParameterRole::dimension;
  double min = 0.0;       ///< numbers: values must be > min (SI)
  double max = INFINITY;  ///< numbers: values must be < max (SI)

  /// The SI unit of the value ("m" for lengths, "1" for counts, "" for names).
  std::string_view unit() const;
};

/// Values of all parameters of one template (lengths in metres), defaults filled in.
struct TemplateValues {
  std::map<std::string, double> numbers;
  std::map<std::string, std::string> texts;
  std::string where;                             ///< "file:line: geometry" for error messages
  std::map<std::string, std::string> key_where;  ///< "file:line: geometry.key" of keys given

  /// A numeric parameter (throws std::out_of_range for a key the template does not declare).
  double operator[](const std::string& key) const { return numbers.at(key); }
  /// A material or name parameter.
  const std::string& text(const std::string& key) const { return texts.at(key); }
};

/// A parametric valve geometry.
struct ValveTemplate {
  std::string name;
  std::string description;
  std::vector<TemplateParameter> parameters;
  /// Builds the outlines; InputError (naming the keys) when the dimensions are inconsistent.
  std::function<std::vector<RegionOutline>(const TemplateValues&)> build;

  /// The keys of its steel walls (parameters with ParameterRole::wall).
  std::vector<std::string> walls() const;
};

/// The templates: annular_valve, radial_valve, meandering_valve, damper_piston, disc_brake.
const std::vector<ValveTemplate>& valve_templates();

/// The template of that name, nullptr if none.
const ValveTemplate* find_template(const std::string& name);

/// The default values of a template's parameters.
TemplateValues default_values(const ValveTemplate& valve);

}  // namespace rheomag::cases
