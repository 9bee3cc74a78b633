// TOML case file -> Case (Problem + metadata).

#include "case/case_file.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

#include "case/case_sections.hpp"
#include "case/femm_import.hpp"
#include "case/femm_sidecar.hpp"
#include "case/region_pslg.hpp"
#include "case/templates.hpp"
#include "case/toml_section.hpp"
#include "case/wire_gauge.hpp"
#include "core/error.hpp"

namespace rheomag::cases {
namespace {

/// Coil turns: a whole number from 1 to 10^9 (FEMM stores turns as an integer; 10^9 turns of the
/// finest wire fill square metres of winding window). 1e15 turns were solved and exported as
/// -9223372036854775808.
constexpr Domain kTurns = Domain::between(1.0, 1e9).whole();

constexpr const char* background_name = "air";

/// The length units a case file may use.
enum class LengthUnit { metre, millimetre };
constexpr auto kLengthUnitNames =
    enum_names<LengthUnit>({{LengthUnit::metre, "m"}, {LengthUnit::millimetre, "mm"}});
constexpr auto kSymmetryNames =
    enum_names<Symmetry>({{Symmetry::axisymmetric, "axisymmetric"}, {Symmetry::planar, "planar"}});
constexpr auto kGapKindNames = enum_names<mesh::GapKind>(
    {{mesh::GapKind::annular, "annular"}, {mesh::GapKind::radial, "radial"}});
constexpr auto kOuterBoundaryNames = enum_names<OuterBoundary>(
    {{OuterBoundary::open, "open"}, {OuterBoundary::dirichlet, "dirichlet"}});

/// Metres per length unit of the file.
double length_unit(const TomlSection& section) {
  return section.choice_or("units", kLengthUnitNames, LengthUnit::metre) == LengthUnit::metre
             ? 1.0
             : 1e-3;
}

/// Reads one [[region]] table: closed polyline with optional per-edge arc angles.
RegionOutline read_region(const TomlSection& section, double unit, double max_arc_degrees) {
  section.allow_only({"name", "material", "points", "mesh_size", "gap", "coil"});
  RegionOutline region;
  region.where = section.where();
  region.name = section.required_string("name");
  if (!section.has("material"))
    section.fail("material", "region '" + region.name + "' has no material");
  region.material = section.required_string("material");
  region.material_where = section.where("material");
  region.mesh_size = section.positive_or("mesh_size", 0.0) * unit;
  region.gap = section.choice_or("gap", kGapKindNames, mesh::GapKind::none);
  if (auto coil = section.table("coil")) {
    coil->allow_only({"circuit", "turns", "reversed"});
    region.circuit = coil->required_string("circuit");
    region.turns = coil->quantity("turns", kTurns);
    if (coil->boolean_or("reversed", false)) region.turns = -region.turns;
  }

  const toml::node* node = section.node("points");
  if (!node) section.fail("points", "missing; expected a closed list of [r, z] points");
  const toml::array* rows = node->as_array();
  if (!rows) section.fail("points", "expected a list of [r, z] or [r, z, arc_degrees] points");
  struct Vertex {
    mesh::Point p;
    double arc = 0.0;
  };
  std::vector<Vertex> vertices;
  for (std::size_t i = 0; i < rows->size(); ++i) {
    const toml::array* row = (*rows)[i].as_array();
    const std::string item = "point " + std::to_string(i + 1);
    if (!row || row->size() < 2 || row->size() > 3)
      section.fail("points", item + ": expected [r, z] or [r, z, arc_degrees]");
    double values[3] = {0.0, 0.0, 0.0};
    for (std::size_t k = 0; k < row->size(); ++k) {
      const toml::node& v = (*row)[k];
      if (auto iv = v.value_exact<int64_t>())
        values[k] = static_cast<double>(*iv);
      else if (auto fv = v.value_exact<double>())
        values[k] = *fv;
      else
        section.fail("points", item + ": expected numbers");
      if (!std::isfinite(values[k])) section.fail("points", item + ": expected finite numbers");
    }
    if (std::abs(values[2]) >= 360.0)
      section.fail("points", item + ": arc angle must lie strictly between -360 and 360 degrees");
    vertices.push_back({{values[0] * unit, values[1] * unit}, values[2]});
  }
  if (vertices.size() < 4)
    section.fail("points",
                 "a closed outline needs at least 3 points plus the first repeated at "
                 "the end, got " +
                     std::to_string(vertices.size()) + " points");
  const mesh::Point first = vertices.front().p, last = vertices.back().p;
  double extent = 0.0;
  for (const Vertex& v : vertices) extent = std::max({extent, std::abs(v.p.r), std::abs(v.p.z)});
  if (std::hypot(first.r - last.r, first.z - last.z) > 1e-9 * extent)
    section.fail("points", "the outline of region '" + region.name +
                               "' is open: its last point must repeat the first point");
  if (vertices.back().arc != 0.0)
    section.fail("points",
                 "the last point closes the outline; put the arc angle on the point "
                 "that starts the edge");
  for (std::size_t i = 0; i + 1 < vertices.size(); ++i) {
    if (region.outline.empty()) region.outline.push_back(vertices[i].p);
    if (vertices[i].arc != 0.0)
      append_arc(region.outline, vertices[i].p, vertices[i + 1].p, vertices[i].arc,
                 max_arc_degrees);
    else
      region.outline.push_back(vertices[i + 1].p);
  }
  region.outline.pop_back();  // the repeated first point
  return region;
}

/// Meridian-plane area of a closed polygon (shoelace) [m^2].
double polygon_area(const std::vector<mesh::Point>& outline) {
  double twice = 0.0;
  for (std::size_t i = 0; i < outline.size(); ++i) {
    const mesh::Point& a = outline[i];
    const mesh::Point& b = outline[(i + 1) % outline.size()];
    twice += a.r * b.z - b.r * a.z;
  }
  return 0.5 * std::abs(twice);
}

/// [geometry] wire + fill_factor; turns and fill_factor together are an error
/// (docs/case-format.md).
Winding read_winding(const TomlSection& geometry) {
  Winding winding;
  if (geometry.has("wire")) {
    winding.wire = geometry.required_string("wire");
    winding.wire_where = geometry.where("wire");
    try {
      winding.wire_diameter = wire_diameter(winding.wire);
    } catch (const InputError& e) {
      geometry.fail("wire", e.what());
    }
  }
  if (!geometry.has("fill_factor")) return winding;
  if (geometry.has("turns"))
    geometry.fail("fill_factor",
                  "give either turns or fill_factor (turns derived from wire and fill), not both");
  if (!geometry.has("wire"))
    geometry.fail("fill_factor", "needs wire = \"AWG 24\" (or \"0.5 mm\") to derive the turns");
  winding.fill_factor = geometry.positive("fill_factor");
  winding.fill_where = geometry.where("fill_factor");
  return winding;
}

/// Every coil region of a template wound from its wire gets the turns that fit its window
/// (winding_turns).
void derive_coil_turns(const Winding& winding, std::vector<RegionOutline>& outlines) {
  if (winding.fill_factor <= 0.0) return;
  for (RegionOutline& region : outlines) {
    if (region.circuit.empty()) continue;
    try {
      region.turns =
          winding_turns(polygon_area(region.outline), winding.wire_diameter, winding.fill_factor);
    } catch (const InputError& e) {
      throw InputError(winding.fill_where + ": " + e.what());
    }
  }
}

/// Reads the [geometry] table of a template case: its parameters, defaults filled in.
TemplateValues read_template(const TomlSection& geometry, const ValveTemplate& valve, double unit) {
  std::vector<std::string_view> known{"template", "max_arc_angle", "background_material", "wire",
                                      "fill_factor"};
  for (const TemplateParameter& p : valve.parameters) known.push_back(p.key);
  geometry.allow_only(known);
  TemplateValues values = default_values(valve);
  values.where = geometry.where();
  for (const TemplateParameter& p : valve.parameters) {
    if (!geometry.has(p.key)) continue;
    values.key_where[p.key] = geometry.where(p.key);
    switch (p.kind) {
      case ParameterKind::length:
        values.numbers[p.key] = geometry.positive(p.key) * unit;
        break;
      case ParameterKind::count:
        values.numbers[p.key] = geometry.quantity(p.key, kTurns);
        break;
      case ParameterKind::material:
      case ParameterKind::name:
        values.texts[p.key] = geometry.required_string(p.key);
        break;
    }
  }
  return values;
}

/// The library material `name`, which must be an MR fluid (have a [rheology] table);
/// InputError "<where>: ..." naming the MR fluids of the library otherwise.
const LibraryMaterial& mr_fluid(const MaterialLibrary& materials, const std::string& name,
                                const std::string& where) {
  const LibraryMaterial& m = materials.get(name, where);
  if (m.rheology) return m;
  std::string fluids;
  for (const std::string& other : materials.names()) {
    const LibraryMaterial* candidate = materials.find(other);
    if (candidate && candidate->rheology) fluids += (fluids.empty() ? "" : ", ") + other;
  }
  throw InputError(where + ": '" + name + "' is not an MR fluid (its material has no [rheology]" +
                   " table); expected one of: " + fluids);
}

}  // namespace

Case parse_case(toml::table table, const std::string& source, const MaterialLibrary& library) {
  Case result;
  result.source = source;
  result.table = std::move(table);
  const TomlSection top(result.table, "", source);
  std::vector<std::string_view> known{"case",   "solver",   "geometry",
                                      "region", "material", "circuit"};
  const std::vector<std::string> later_sections = registered_case_sections();
  for (const std::string& s : later_sections) known.push_back(s);
  top.allow_only(known);

  Problem& problem = result.problem;
  CaseInput& input = result.input;
  double unit = 1.0;
  result.name = std::filesystem::path(source).stem().string();
  if (auto section = top.table("case")) {
    section->allow_only({"name", "description", "units", "symmetry", "depth", "fluid"});
    result.name = section->string("name").value_or(result.name);
    result.description = section->string("description").value_or("");
    unit = length_unit(*section);
    problem.symmetry = section->choice_or("symmetry", kSymmetryNames, Symmetry::axisymmetric);
    if (section->has("depth") && problem.symmetry != Symmetry::planar)
      section->fail("depth", "depth applies to planar cases only");
    problem.depth = section->positive_or("depth", 1.0 / unit) * unit;
    input.fluid = section->string("fluid").value_or("");
    input.fluid_where = section->where("fluid");
  }
  input.length_unit = unit;

  // Materials: the library plus inline [[material]] tables (which shadow library entries).
  input.library = std::make_shared<const MaterialLibrary>(library);
  input.materials = library;
  for (const TomlSection& section : top.table_array("material"))
    input.materials.add(read_material(section));

  // Circuits.
  for (const TomlSection& section : top.table_array("circuit")) {
    section.allow_only({"name", "current"});
    Circuit circuit;
    circuit.name = section.required_string("name");
    circuit.current = section.number_or("current", 0.0);
    for (const Circuit& earlier : problem.circuits)
      if (earlier.name == circuit.name)
        section.fail("name", "circuit '" + circuit.name + "' is defined twice");
    problem.circuits.push_back(circuit);
  }

  // Geometry: a template or general regions.
  const std::optional<TomlSection> geometry = top.table("geometry");
  const std::vector<TomlSection> region_tables = top.table_array("region");
  double max_arc_degrees = 5.0;
  input.background_where = source;
  if (geometry) {
    max_arc_degrees = geometry->number_or("max_arc_angle", 5.0);
    if (!(max_arc_degrees >= 0.1 && max_arc_degrees <= 90.0))
      geometry->fail("max_arc_angle",
                     "expected degrees in [0.1, 90], got " + format_number(max_arc_degrees));
    input.background_material =
        geometry->string("background_material").value_or(input.background_material);
    input.background_where = geometry->where("background_material");
  }
  if (geometry && geometry->has("template")) {
    if (!region_tables.empty())
      top.fail("region", "give either [geometry] template = ... or [[region]] tables, not both");
    const std::string name = geometry->required_string("template");
    input.valve = find_template(name);
    if (!input.valve) {
      std::vector<std::string_view> names;
      for (const ValveTemplate& t : valve_templates()) names.push_back(t.name);
      std::string message = "unknown template '" + name + "'";
      const std::string suggestion = closest_key(name, names);
      if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
      geometry->fail("template", message);
    }
    result.geometry_template = input.valve->name;
    input.template_values = read_template(*geometry, *input.valve, unit);
    input.winding = read_winding(*geometry);
  } else {
    if (geometry) geometry->allow_only({"max_arc_angle", "background_material"});
    if (region_tables.empty())
      throw InputError(source +
                       ": no geometry: add [geometry] template = \"annular_valve\" (or "
                       "radial_valve, meandering_valve) or [[region]] tables");
    for (const TomlSection& section : region_tables)
      input.regions.push_back(read_region(section, unit, max_arc_degrees));
  }

  // Solver options.
  problem.outer = OuterBoundary::open;
  if (auto solver = top.table("solver")) {
    solver->allow_only({"order", "min_gap_elements", "outer_boundary", "outer_radius_factor"});
    const long long order = solver->integer_or("order", 2);
    if (order != 1 && order != 2) solver->fail("order", "expected 1 or 2");
    problem.order = static_cast<int>(order);
    const long long min_gap = solver->integer_or("min_gap_elements", 4);
    if (min_gap < 1 || min_gap > 100) solver->fail("min_gap_elements", "expected 1 to 100");
    problem.min_gap_elements = static_cast<int>(min_gap);
    problem.outer = solver->choice_or("outer_boundary", kOuterBoundaryNames, OuterBoundary::open);
    // Beyond 100 bounding radii the open boundary gains nothing and the geometry's points
    // merge within the mesher's tolerance, which is relative to the whole domain.
    problem.outer_radius_factor =
        solver->quantity_or("outer_radius_factor", Domain::between(1.0, 100.0).above(1.0), 5.0);
  }
  build_case(result);
  return result;
}

Case parse_case(std::string_view text, const std::string& source, const MaterialLibrary& library) {
  return parse_case(parse_toml(text, source), source, library);
}

void build_case(Case& c) {
  const CaseInput& input = c.input;
  Problem& problem = c.problem;
  const double unit = input.length_unit;
  const std::string source = c.source.string();
  std::vector<RegionOutline> outlines = input.regions;
  if (input.valve) {
    outlines = input.valve->build(input.template_values);
    derive_coil_turns(input.winding, outlines);
  }

  // Names must be unique (a set of those seen: 10^5 regions take no pairwise comparison); the
  // background name is reserved.
  std::set<std::string> names;
  for (std::size_t i = 0; i < outlines.size(); ++i) {
    if (outlines[i].name == background_name)
      throw InputError(outlines[i].where +
                       ": region name 'air' is reserved for the background "
                       "(the space between regions); choose another name");
    if (!names.insert(outlines[i].name).second)
      throw InputError(outlines[i].where + ": region name '" + outlines[i].name +
                       "' is used twice");
  }
  if (problem.symmetry == Symmetry::axisymmetric) {
    for (const RegionOutline& region : outlines)
      for (const mesh::Point& p : region.outline)
        if (p.r < -1e-12)
          throw InputError(region.where + ": region '" + region.name +
                           "' has a point at negative r = " + format_number(p.r / unit) +
                           " (axisymmetric cases live in r >= 0)");
  }

  problem.geometry = outlines_to_pslg(outlines, source, background_name);

  // Region data: materials (in order of first use), coils.
  problem.regions.clear();
  problem.materials.clear();
  const MaterialLibrary& materials = input.materials;
  std::map<std::string, int> material_index;
  auto use_material = [&](const std::string& name, const std::string& where) {
    const LibraryMaterial& m = materials.get(name, where);
    const std::string key = normalised_material_name(m.magnetic.name);
    auto it = material_index.find(key);
    if (it != material_index.end()) return it->second;
    const int index = static_cast<int>(problem.materials.size());
    problem.materials.push_back(m.magnetic);
    material_index[key] = index;
    return index;
  };
  for (const RegionOutline& region : outlines) {
    RegionData data;
    data.material = use_material(
        region.material, (region.material_where.empty() ? region.where : region.material_where) +
                             ": region '" + region.name + "'");
    if (!region.circuit.empty()) {
      int circuit = -1;
      for (std::size_t k = 0; k < problem.circuits.size(); ++k)
        if (problem.circuits[k].name == region.circuit) circuit = static_cast<int>(k);
      if (circuit < 0)
        throw InputError(region.where + ": region '" + region.name + "': unknown circuit '" +
                         region.circuit + "'; add [[circuit]] name = \"" + region.circuit +
                         "\" current = ... (amperes)");
      data.circuit = circuit;
      data.turns = region.turns;
    }
    problem.regions.push_back(data);
  }
  RegionData air;
  air.material = use_material(input.background_material, input.background_where);
  problem.regions.push_back(air);

  // MR fluid of the gaps: [case] fluid, else the material of the first gap; every gap holds it.
  c.fluid.clear();
  if (!input.fluid.empty())
    c.fluid = mr_fluid(materials, input.fluid, input.fluid_where).magnetic.name;
  if (input.valve)
    for (const TemplateParameter& p : input.valve->parameters) {
      if (p.role != ParameterRole::fluid) continue;
      const auto given = input.template_values.key_where.find(p.key);
      mr_fluid(materials, input.template_values.text(p.key),
               given != input.template_values.key_where.end()
                   ? given->second
                   : input.template_values.where + " (default " + p.key + ")");
    }
  for (const RegionOutline& region : outlines) {
    if (region.gap == mesh::GapKind::none) continue;
    const std::string where =
        (region.material_where.empty() ? region.where : region.material_where) + ": gap '" +
        region.name + "'";
    const std::string name = mr_fluid(materials, region.material, where).magnetic.name;
    if (c.fluid.empty()) c.fluid = name;
    if (normalised_material_name(name) != normalised_material_name(c.fluid))
      throw InputError(where + " holds '" + name + "'; expected the case's MR fluid '" + c.fluid +
                       "' (" + (input.fluid.empty() ? "that of the first gap" : input.fluid_where) +
                       "): one fluid fills every gap");
  }
}

std::string case_file_text(const Case& c) {
  std::ostringstream out;
  out << c.table;
  return out.str();
}

Case read_case_file(const std::filesystem::path& path, const MaterialLibrary& library) {
  return parse_case(read_input_file(path.string()), path.string(), library);
}

Case load_case(const std::filesystem::path& path, const MaterialLibrary& library) {
  std::string extension = path.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension == ".fem") {
    Case result;
    result.source = path;
    result.name = path.stem().string();
    result.problem = read_femm_file(path);
    result.femm = true;
    result.input.library = std::make_shared<const MaterialLibrary>(library);
    const std::filesystem::path sidecar = femm_sidecar_path(path);
    if (is_femm_sidecar(sidecar)) apply_femm_sidecar(result, sidecar, library);
    return result;
  }
  if (extension == ".toml") return read_case_file(path, library);
  throw InputError(path.string() + ": unknown case file type '" + extension +
                   "'; expected a .toml case or a FEMM .fem file");
}

}  // namespace rheomag::cases
