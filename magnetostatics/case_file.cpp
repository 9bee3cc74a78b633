// TOML case file -> Case (Problem + metadata).

#include "magnetostatics/case_file.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include "magnetostatics/femm_import.hpp"
#include "magnetostatics/region_pslg.hpp"
#include "magnetostatics/templates.hpp"
#include "magnetostatics/toml_section.hpp"
#include "magnetostatics/wire_gauge.hpp"
#include "mesh/error.hpp"

namespace rheomag::magnetostatics {
namespace {

constexpr const char* background_name = "air";

/// Metres per length unit of the file.
double length_unit(const TomlSection& section) {
  const std::string units = section.string("units").value_or("m");
  if (units == "m") return 1.0;
  if (units == "mm") return 1e-3;
  section.fail("units", "expected \"m\" or \"mm\", got \"" + units + "\"");
}

mesh::GapKind gap_kind(const TomlSection& section) {
  const std::optional<std::string> kind = section.string("gap");
  if (!kind) return mesh::GapKind::none;
  if (*kind == "annular") return mesh::GapKind::annular;
  if (*kind == "radial") return mesh::GapKind::radial;
  section.fail("gap", "expected \"annular\" or \"radial\", got \"" + *kind + "\"");
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
  region.gap = gap_kind(section);
  if (auto coil = section.table("coil")) {
    coil->allow_only({"circuit", "turns", "reversed"});
    region.circuit = coil->required_string("circuit");
    region.turns = coil->positive("turns");
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

/// [geometry] fill_factor + wire: every coil region of the template gets the turns that fit its
/// window (winding_turns); turns and fill_factor together are an error (docs/case-format.md).
void derive_coil_turns(const TomlSection& geometry, std::vector<RegionOutline>& outlines) {
  if (geometry.has("wire")) {
    try {
      wire_diameter(geometry.required_string("wire"));
    } catch (const InputError& e) {
      geometry.fail("wire", e.what());
    }
  }
  if (!geometry.has("fill_factor")) return;
  if (geometry.has("turns"))
    geometry.fail("fill_factor",
                  "give either turns or fill_factor (turns derived from wire and fill), not both");
  if (!geometry.has("wire"))
    geometry.fail("fill_factor", "needs wire = \"AWG 24\" (or \"0.5 mm\") to derive the turns");
  const double diameter = wire_diameter(geometry.required_string("wire"));
  const double fill = geometry.positive("fill_factor");
  for (RegionOutline& region : outlines) {
    if (region.circuit.empty()) continue;
    try {
      region.turns = winding_turns(polygon_area(region.outline), diameter, fill);
    } catch (const InputError& e) {
      geometry.fail("fill_factor", e.what());
    }
  }
}

/// Reads the [geometry] table of a template case into outlines.
std::vector<RegionOutline> read_template(const TomlSection& geometry, const ValveTemplate& valve,
                                         double unit) {
  std::vector<std::string_view> known{"template", "max_arc_angle", "background_material", "wire",
                                      "fill_factor"};
  for (const TemplateParameter& p : valve.parameters) known.push_back(p.key);
  geometry.allow_only(known);
  TemplateValues values = default_values(valve);
  values.where = geometry.where();
  for (const TemplateParameter& p : valve.parameters) {
    if (!geometry.has(p.key)) continue;
    switch (p.kind) {
      case ParameterKind::length:
        values.numbers[p.key] = geometry.positive(p.key) * unit;
        break;
      case ParameterKind::count:
        values.numbers[p.key] = geometry.positive(p.key);
        break;
      case ParameterKind::material:
      case ParameterKind::name:
        values.texts[p.key] = geometry.required_string(p.key);
        break;
    }
  }
  std::vector<RegionOutline> outlines = valve.build(values);
  derive_coil_turns(geometry, outlines);
  return outlines;
}

}  // namespace

const std::vector<std::string_view>& case_sections_of_later_links() {
  static const std::vector<std::string_view> sections{"fluid",  "valve",    "damper",
                                                      "lumped", "optimise", "identify"};
  return sections;
}

Case parse_case(std::string_view text, const std::string& source, const MaterialLibrary& library) {
  Case result;
  result.source = source;
  result.table = parse_toml(text, source);
  const TomlSection top(result.table, "", source);
  std::vector<std::string_view> known{"case",   "solver",   "geometry",
                                      "region", "material", "circuit"};
  for (std::string_view s : case_sections_of_later_links()) known.push_back(s);
  top.allow_only(known);

  Problem& problem = result.problem;
  double unit = 1.0;
  result.name = std::filesystem::path(source).stem().string();
  std::string fluid_key_where;
  if (auto section = top.table("case")) {
    section->allow_only({"name", "description", "units", "symmetry", "depth", "fluid"});
    result.name = section->string("name").value_or(result.name);
    result.description = section->string("description").value_or("");
    unit = length_unit(*section);
    const std::string symmetry = section->string("symmetry").value_or("axisymmetric");
    if (symmetry == "axisymmetric")
      problem.symmetry = Symmetry::axisymmetric;
    else if (symmetry == "planar")
      problem.symmetry = Symmetry::planar;
    else
      section->fail("symmetry",
                    "expected \"axisymmetric\" or \"planar\", got \"" + symmetry + "\"");
    if (section->has("depth") && problem.symmetry != Symmetry::planar)
      section->fail("depth", "depth applies to planar cases only");
    problem.depth = section->positive_or("depth", 1.0 / unit) * unit;
    result.fluid = section->string("fluid").value_or("");
    fluid_key_where = section->where("fluid");
  }

  // Materials: the library plus inline [[material]] tables (which shadow library entries).
  MaterialLibrary materials = library;
  for (const TomlSection& section : top.table_array("material"))
    materials.add(read_material(section));

  // Circuits.
  std::map<std::string, int> circuit_index;
  for (const TomlSection& section : top.table_array("circuit")) {
    section.allow_only({"name", "current"});
    Circuit circuit;
    circuit.name = section.required_string("name");
    circuit.current = section.number_or("current", 0.0);
    if (circuit_index.count(circuit.name))
      section.fail("name", "circuit '" + circuit.name + "' is defined twice");
    circuit_index[circuit.name] = static_cast<int>(problem.circuits.size());
    problem.circuits.push_back(circuit);
  }

  // Geometry: a template or general regions.
  std::vector<RegionOutline> outlines;
  std::string background_material = "Air";
  const std::optional<TomlSection> geometry = top.table("geometry");
  const std::vector<TomlSection> region_tables = top.table_array("region");
  double max_arc_degrees = 5.0;
  if (geometry) {
    max_arc_degrees = geometry->number_or("max_arc_angle", 5.0);
    if (!(max_arc_degrees >= 0.1 && max_arc_degrees <= 90.0))
      geometry->fail("max_arc_angle",
                     "expected degrees in [0.1, 90], got " + format_number(max_arc_degrees));
    background_material = geometry->string("background_material").value_or(background_material);
  }
  if (geometry && geometry->has("template")) {
    if (!region_tables.empty())
      top.fail("region", "give either [geometry] template = ... or [[region]] tables, not both");
    const std::string name = geometry->required_string("template");
    const ValveTemplate* valve = find_template(name);
    if (!valve) {
      std::vector<std::string_view> names;
      for (const ValveTemplate& t : valve_templates()) names.push_back(t.name);
      std::string message = "unknown template '" + name + "'";
      const std::string suggestion = closest_key(name, names);
      if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
      geometry->fail("template", message);
    }
    result.geometry_template = valve->name;
    outlines = read_template(*geometry, *valve, unit);
  } else {
    if (geometry) geometry->allow_only({"max_arc_angle", "background_material"});
    if (region_tables.empty())
      throw InputError(source +
                       ": no geometry: add [geometry] template = \"annular_valve\" (or "
                       "radial_valve, meandering_valve) or [[region]] tables");
    for (const TomlSection& section : region_tables)
      outlines.push_back(read_region(section, unit, max_arc_degrees));
  }

  // Names must be unique; the background name is reserved.
  for (std::size_t i = 0; i < outlines.size(); ++i) {
    if (outlines[i].name == background_name)
      throw InputError(outlines[i].where +
                       ": region name 'air' is reserved for the background "
                       "(the space between regions); choose another name");
    for (std::size_t j = 0; j < i; ++j)
      if (outlines[j].name == outlines[i].name)
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
      auto it = circuit_index.find(region.circuit);
      if (it == circuit_index.end())
        throw InputError(region.where + ": region '" + region.name + "': unknown circuit '" +
                         region.circuit + "'; add [[circuit]] name = \"" + region.circuit +
                         "\" current = ... (amperes)");
      data.circuit = it->second;
      data.turns = region.turns;
    }
    problem.regions.push_back(data);
  }
  RegionData air;
  air.material =
      use_material(background_material, geometry ? geometry->where("background_material") : source);
  problem.regions.push_back(air);

  // MR fluid of the gaps.
  if (result.fluid.empty()) {
    for (const RegionOutline& region : outlines)
      if (region.gap != mesh::GapKind::none) {
        result.fluid = materials.get(region.material, region.where).magnetic.name;
        break;
      }
  } else {
    result.fluid = materials.get(result.fluid, fluid_key_where).magnetic.name;
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
    const std::string outer = solver->string("outer_boundary").value_or("open");
    if (outer == "open")
      problem.outer = OuterBoundary::open;
    else if (outer == "dirichlet")
      problem.outer = OuterBoundary::dirichlet;
    else
      solver->fail("outer_boundary", "expected \"open\" or \"dirichlet\", got \"" + outer + "\"");
    problem.outer_radius_factor = solver->number_or("outer_radius_factor", 5.0);
    if (!(problem.outer_radius_factor > 1.0))
      solver->fail("outer_radius_factor", "expected a number > 1");
  }
  return result;
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
    return result;
  }
  if (extension == ".toml") return read_case_file(path, library);
  throw InputError(path.string() + ": unknown case file type '" + extension +
                   "'; expected a .toml case or a FEMM .fem file");
}

}  // namespace rheomag::magnetostatics
