#include "sweep/spec.hpp"

#include <cmath>
#include <limits>
#include <set>

#include "case/toml_section.hpp"
#include "core/error.hpp"

namespace rheomag::sweep {

namespace {

using cases::format_number;
using cases::TomlSection;

/// A number of the axis converted to the key's type (integers are rounded to the nearest).
cases::KeyValue numeric_level(const TomlSection& axis, const cases::CaseKey& key, double value) {
  if (key.type == cases::KeyType::integer) {
    const double rounded = std::round(value);
    if (std::fabs(rounded) > 9.0e15) axis.fail("key", "integer level out of range");
    return static_cast<long long>(rounded);
  }
  if (key.type == cases::KeyType::number) return value;
  axis.fail("key", "'" + key.written + "' holds a " +
                       (key.type == cases::KeyType::text ? std::string("string") : "boolean") +
                       " in the base case; give its levels with 'values'");
}

/// One element of an axis's `values` list, checked against the key's type.
cases::KeyValue list_level(const TomlSection& axis, const cases::CaseKey& key,
                           const toml::node& node, std::size_t index) {
  const std::string what = "values[" + std::to_string(index) + "]";
  switch (key.type) {
    case cases::KeyType::integer:
      if (auto v = node.value_exact<int64_t>()) return static_cast<long long>(*v);
      if (auto v = node.value_exact<double>(); v && std::isfinite(*v) && std::trunc(*v) == *v) {
        return static_cast<long long>(*v);
      }
      axis.fail("values", what + ": '" + key.written +
                              "' is an integer in the base case; expected an integer");
    case cases::KeyType::number:
      if (auto v = node.value<double>(); v && std::isfinite(*v) && !node.is_boolean()) return *v;
      axis.fail("values", what + ": expected a finite number for '" + key.written + "'");
    case cases::KeyType::boolean:
      if (auto v = node.value_exact<bool>()) return *v;
      axis.fail("values", what + ": expected true or false for '" + key.written + "'");
    case cases::KeyType::text:
      if (auto v = node.value_exact<std::string>()) return *v;
      axis.fail("values",
                what + ": '" + key.written + "' is a string in the base case; expected a string");
  }
  axis.fail("values", what + ": unsupported value");
}

std::vector<cases::KeyValue> list_levels(const TomlSection& axis, const cases::CaseKey& key) {
  const toml::array* list = axis.node("values")->as_array();
  if (!list || list->empty()) axis.fail("values", "expected a non-empty list");
  std::vector<cases::KeyValue> levels;
  for (std::size_t i = 0; i < list->size(); ++i) {
    levels.push_back(list_level(axis, key, *list->get(i), i));
  }
  return levels;
}

/// start/stop with count (evenly spaced, both ends included) or step (start, start + step, ...
/// up to stop within 1e-9 of a step).
std::vector<cases::KeyValue> range_levels(const TomlSection& axis, const cases::CaseKey& key) {
  if (!axis.has("start") || !axis.has("stop")) {
    axis.fail("start",
              "a range needs 'start' and 'stop' (and 'count' or 'step'), or give 'values'");
  }
  const double start = *axis.number("start");
  const double stop = *axis.number("stop");
  if (axis.has("count") == axis.has("step")) {
    axis.fail("count", "a range needs exactly one of 'count' and 'step'");
  }
  long long count = 0;
  double step = 0.0;
  if (axis.has("count")) {
    count = axis.integer_or("count", 0);
    if (count < 1) axis.fail("count", "expected an integer >= 1");
    if (count == 1 && start != stop) axis.fail("count", "count = 1 needs start = stop");
    step = count > 1 ? (stop - start) / static_cast<double>(count - 1) : 0.0;
  } else {
    step = *axis.number("step");
    if (step == 0.0) axis.fail("step", "expected a non-zero step");
    const double intervals = (stop - start) / step;
    if (intervals < -1e-9) {
      axis.fail("step",
                "step " + format_number(step) + " goes away from stop " + format_number(stop));
    }
    if (intervals > static_cast<double>(kMaxDesigns)) axis.fail("step", "too many levels");
    count = static_cast<long long>(std::floor(intervals + 1e-9)) + 1;
  }
  if (count > kMaxDesigns) axis.fail("count", "too many levels");
  std::vector<cases::KeyValue> levels;
  for (long long i = 0; i < count; ++i) {
    // The last level of a counted range is `stop` exactly (no rounding drift).
    const double value = (axis.has("count") && i == count - 1) ? stop : start + step * double(i);
    levels.push_back(numeric_level(axis, key, value));
  }
  return levels;
}

SweepAxis parse_axis(const TomlSection& axis, const SweepSpec& spec) {
  axis.allow_only({"key", "values", "start", "stop", "count", "step", "min", "max"});
  SweepAxis result;
  result.key = cases::resolve_case_key(spec.base, axis.required_string("key"), axis.where("key"),
                                       "sweep key");
  const bool lhs = spec.method == SweepMethod::latin_hypercube;
  const bool has_range =
      axis.has("start") || axis.has("stop") || axis.has("count") || axis.has("step");
  const bool has_bounds = axis.has("min") || axis.has("max");
  if (axis.has("values") + has_range + has_bounds != 1) {
    axis.fail("key",
              "give exactly one of: 'values' (a list), a range (start, stop, count or "
              "step) or bounds (min, max; Latin hypercube)");
  }
  if (axis.has("values")) {
    result.levels = list_levels(axis, result.key);
  } else if (has_range) {
    if (lhs) axis.fail("start", "a Latin hypercube axis takes bounds 'min' and 'max' or 'values'");
    result.levels = range_levels(axis, result.key);
  } else {
    if (!lhs) axis.fail("min", "bounds 'min'/'max' are for method = \"latin_hypercube\"");
    if (result.key.type != cases::KeyType::integer && result.key.type != cases::KeyType::number) {
      axis.fail("min", "bounds need a numeric key; '" + result.key.written + "' is not");
    }
    if (!axis.has("min") || !axis.has("max")) axis.fail("min", "give both 'min' and 'max'");
    result.lower = *axis.number("min");
    result.upper = *axis.number("max");
    if (!(result.lower < result.upper)) axis.fail("max", "expected max > min");
  }
  return result;
}

}  // namespace

SweepSpec parse_sweep(std::string_view text, const std::filesystem::path& source) {
  const std::string file = source.string();
  const toml::table root = cases::parse_toml(text, file);
  const TomlSection top(root, "", file);
  top.allow_only({"sweep", "axis", "output"});
  SweepSpec spec;
  spec.source = source;
  const std::optional<TomlSection> sweep = top.table("sweep");
  if (!sweep) throw InputError(file + ": missing [sweep] table (with base = \"case.toml\")");
  sweep->allow_only({"base", "method", "samples", "seed"});
  const std::filesystem::path base = sweep->required_string("base");
  spec.base_case = base.is_absolute() ? base : source.parent_path() / base;
  if (!std::filesystem::is_regular_file(spec.base_case)) {
    sweep->fail("base", "base case '" + spec.base_case.string() + "' is not a readable file");
  }
  spec.base = cases::load_case(spec.base_case);
  if (spec.base.table.empty() && !spec.base.femm) {
    sweep->fail("base", "the base case must be a TOML case file (its keys are what is swept)");
  }
  const std::string method = sweep->string("method").value_or("factorial");
  if (method == "factorial") {
    spec.method = SweepMethod::factorial;
    if (sweep->has("samples") || sweep->has("seed")) {
      sweep->fail("samples", "'samples' and 'seed' are for method = \"latin_hypercube\"");
    }
  } else if (method == "latin_hypercube") {
    spec.method = SweepMethod::latin_hypercube;
    spec.samples = sweep->integer_or("samples", 0);
    if (spec.samples < 1 || spec.samples > kMaxDesigns) {
      sweep->fail("samples", "expected an integer from 1 to " + std::to_string(kMaxDesigns));
    }
    const long long seed = sweep->integer_or("seed", 1);
    if (seed < 0) sweep->fail("seed", "expected an integer >= 0");
    spec.seed = static_cast<std::uint64_t>(seed);
  } else {
    sweep->fail("method",
                "unknown method '" + method + "'; expected \"factorial\" or \"latin_hypercube\"");
  }
  const std::vector<TomlSection> axes = top.table_array("axis");
  if (axes.empty()) throw InputError(file + ": no [[axis]] tables; a sweep needs at least one");
  std::set<std::string> seen;
  for (const TomlSection& axis : axes) {
    spec.axes.push_back(parse_axis(axis, spec));
    const std::string canonical = [&] {
      std::string s;
      for (const std::string& p : spec.axes.back().key.path) {
        if (!s.empty()) s += '.';
        s += p;
      }
      return s;
    }();
    if (!seen.insert(canonical).second) axis.fail("key", "key swept twice: '" + canonical + "'");
  }
  if (auto output = top.table("output")) {
    output->allow_only({"csv", "vtu"});
    spec.csv = output->string("csv").value_or(spec.csv);
    if (spec.csv.empty() || std::filesystem::path(spec.csv).filename().empty()) {
      output->fail("csv", "expected a file name such as \"results.csv\"");
    }
    // Outputs stay inside --out: no root, no "..". Links are resolved when the run starts
    // (results_path), where the output folder is known.
    const std::filesystem::path csv(spec.csv);
    if (csv.has_root_name() || csv.has_root_directory())
      output->fail("csv", "\"" + spec.csv +
                              "\" is an absolute path; expected a path inside the output folder "
                              "(--out), such as \"results.csv\"");
    for (const auto& part : csv)
      if (part == "..")
        output->fail("csv", "\"" + spec.csv +
                                "\" leaves the output folder through '..'; expected a path inside "
                                "it (--out), such as \"results.csv\"");
    spec.csv_where = output->where("csv");
    spec.write_vtu = output->boolean_or("vtu", false);
  }
  if (spec.csv_where.empty()) spec.csv_where = file + ": output.csv (default \"results.csv\")";
  if (design_count(spec) > kMaxDesigns) {
    throw InputError(file + ": the sweep has more than " + std::to_string(kMaxDesigns) +
                     " designs; split it");
  }
  return spec;
}

SweepSpec read_sweep(const std::filesystem::path& path) {
  return parse_sweep(cases::read_input_file(path.string()), path);
}

long long design_count(const SweepSpec& spec) {
  if (spec.method == SweepMethod::latin_hypercube) return spec.samples;
  long long count = 1;
  for (const SweepAxis& axis : spec.axes) {
    const long long n = static_cast<long long>(axis.levels.size());
    if (count > std::numeric_limits<long long>::max() / n)
      return std::numeric_limits<long long>::max();
    count *= n;
  }
  return count;
}

}  // namespace rheomag::sweep
