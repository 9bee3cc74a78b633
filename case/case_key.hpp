#pragma once
// The one key API of a case: a dotted key ("geometry.gap_width", "circuit.0.current",
// "valve.flow") resolved once against a base case, its value read, and design edits applied to
// the typed case without going through text.

#include <string>
#include <variant>
#include <vector>

#include "case/case_file.hpp"

namespace rheomag::cases {

/// A value a design gives to a case key (file units, as the case file writes it).
using KeyValue = std::variant<long long, double, bool, std::string>;

/// The TOML type of the value a key holds (edits keep it).
enum class KeyType { integer, number, boolean, text };

/// What an edit of the key changes in the typed case.
enum class KeyTarget {
  template_parameter,  ///< a parameter of the case's template (its default when not written)
  circuit_current,     ///< the current of one [[circuit]]
  wire_gauge,          ///< "wire_gauge": the AWG number of [geometry] wire (real while optimising)
  fluid,               ///< "fluid": [case] fluid and the template's fluid_material together
  element_order,       ///< "solver.order" of a .fem model (which has no [solver] document)
  document,            ///< any other value of the file: the case is read again from its table
};

/// A key resolved against a base case.
struct CaseKey {
  std::string written;             ///< as the user wrote it
  std::vector<std::string> path;   ///< canonical components, e.g. {"circuit", "0", "current"}
  KeyType type = KeyType::number;  ///< type of the base value
  KeyTarget target = KeyTarget::document;
  int circuit = -1;                            ///< circuit_current: index into Problem::circuits
  std::string parameter;                       ///< template_parameter: its key
  ParameterKind kind = ParameterKind::length;  ///< template_parameter: what it holds
  double si_per_unit = 1.0;  ///< SI value of one file unit (lengths of a "mm" case: 1e-3)
};

/// The special key of the coil's wire gauge (AWG number) as a design variable.
inline constexpr const char* kWireGaugeKey = "wire_gauge";

/// Resolves `key` (components separated by '.', an array index as ".N" or "[N]"; the index of an
/// array holding exactly one table may be left out; template parameters resolve even when the
/// file leaves them at their defaults; "wire_gauge" and "fluid" are special keys). InputError
/// "<where>: <label> '<key>' ..." with the closest existing key when it does not exist or is not
/// a single value.
CaseKey resolve_case_key(const Case& base, const std::string& key, const std::string& where,
                         const std::string& label = "key");

/// The value of a resolved key in `c` (file units; a template default when not written).
KeyValue case_value(const Case& c, const CaseKey& key);

/// The numeric value of a resolved key; InputError (prefixed by `where`) if it is not a number.
double numeric_case_value(const Case& c, const CaseKey& key, const std::string& where);

/// One design edit: a resolved key and its new value (file units).
struct CaseEdit {
  CaseKey key;
  KeyValue value;
};

/// A copy of `base` with the edits applied to its typed values (and to its document, so the
/// case can be written out) and its problem rebuilt. InputError when the design is invalid
/// (e.g. a template's dimensions that do not fit together).
Case with(const Case& base, const std::vector<CaseEdit>& edits);

/// One "KEY=VALUE" setting of a command line (`--set geometry.coil_turns=800`): the key resolved
/// against `base` (InputError naming `option`, the setting and the closest existing key) and the
/// value read as the key's type (file units; a length parameter or a circuit current may also
/// carry a unit, "1.2mm", "500mA", converted to the case's unit).
CaseEdit parse_setting(const Case& base, const std::string& setting, const std::string& option);

/// `base` with the `--set` settings applied (parse_setting + with); the case's description then
/// names the edits (the file's own text may no longer hold, e.g. its turns).
Case with_settings(const Case& base, const std::vector<std::string>& settings,
                   const std::string& option);

/// True when every edit only changes circuit currents (same geometry, materials and mesh).
bool only_currents(const std::vector<CaseEdit>& edits);

/// Every value key of a case (canonical dotted form, template defaults included), sorted.
std::vector<std::string> value_keys(const Case& c);

/// The value as written in a CSV cell and in messages (real numbers with 12 significant digits).
std::string format_value(const KeyValue& value);

/// The [geometry] wire text of AWG gauge `n`: "AWG n" for a whole n >= 1, "AWG 0", "AWG 00", ...
/// for whole n <= 0, otherwise the bare diameter "0.51234567 mm".
std::string wire_text(double n);

}  // namespace rheomag::cases
