#include "case/femm_sidecar.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>

#include "case/case_sections.hpp"
#include "case/toml_section.hpp"
#include "core/error.hpp"
#include "core/format_text.hpp"

namespace rheomag::cases {
namespace {

constexpr auto kSidecarGapKinds = enum_names<mesh::GapKind>(
    {{mesh::GapKind::annular, "annular"}, {mesh::GapKind::radial, "radial"}});

/// "name (r, z) m at file:line" of every non-hole label, for messages.
std::string label_list(const mesh::Pslg& g) {
  std::string out;
  for (const mesh::RegionSeed& seed : g.regions) {
    if (seed.hole) continue;
    out += (out.empty() ? "" : "; ") +
           format_text("'%s' (%.6g, %.6g) m", seed.name.c_str(), seed.seed.r, seed.seed.z);
  }
  return out;
}

/// The region a [[fem.gap]] entry names by `label = [r, z]` [m] or `block = "name"`.
int sidecar_region(const Problem& problem, const TomlSection& gap) {
  const mesh::Pslg& g = problem.geometry;
  double extent = 0.0;
  for (const mesh::Point& p : g.points) extent = std::max({extent, std::abs(p.r), std::abs(p.z)});
  if (gap.has("label") == gap.has("block"))
    gap.fail("label", "give either label = [r, z] (metres) or block = \"name\"");
  if (gap.has("block")) {
    const std::string name = gap.required_string("block");
    for (int r = 0; r < static_cast<int>(g.regions.size()); ++r)
      if (!g.regions[r].hole && g.regions[r].name == name) return r;
    gap.fail("block",
             "no block label '" + name + "' in " + g.source + "; its labels are " + label_list(g));
  }
  const std::vector<double> at = gap.numbers("label");
  if (at.size() != 2) gap.fail("label", "expected [r, z] in metres");
  for (int r = 0; r < static_cast<int>(g.regions.size()); ++r) {
    const mesh::Point& s = g.regions[r].seed;
    if (!g.regions[r].hole && std::hypot(s.r - at[0], s.z - at[1]) <= 1e-9 * extent) return r;
  }
  gap.fail("label", format_text("no block label at (%.9g, %.9g) m in %s; its labels are ", at[0],
                                at[1], g.source.c_str()) +
                        label_list(g));
}

/// Puts the regions `first` (in that order) before all others; default region index kept valid.
void move_regions_first(Problem& problem, const std::vector<int>& first) {
  const int n = static_cast<int>(problem.regions.size());
  std::vector<int> order = first;
  for (int r = 0; r < n; ++r)
    if (std::find(first.begin(), first.end(), r) == first.end()) order.push_back(r);
  std::vector<mesh::RegionSeed> seeds;
  std::vector<RegionData> data;
  int default_region = -1;
  for (int k = 0; k < n; ++k) {
    seeds.push_back(problem.geometry.regions[order[k]]);
    data.push_back(problem.regions[order[k]]);
    if (order[k] == problem.geometry.default_region) default_region = k;
  }
  problem.geometry.regions = std::move(seeds);
  problem.regions = std::move(data);
  problem.geometry.default_region = default_region;
}

}  // namespace

std::filesystem::path femm_sidecar_path(const std::filesystem::path& fem) {
  std::filesystem::path out = fem;
  return out.replace_extension(".toml");
}

std::string case_document_source(const Case& c) {
  return (c.femm ? femm_sidecar_path(c.source) : c.source).string();
}

bool is_femm_sidecar(const std::filesystem::path& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) return false;
  const toml::table table = parse_toml_file(path.string());
  return table.contains("fem");
}

void apply_femm_sidecar(Case& c, const std::filesystem::path& path,
                        const MaterialLibrary& library) {
  c.table = parse_toml_file(path.string());
  const TomlSection top(c.table, "", path.string());
  std::vector<std::string_view> known{"fem", "solver"};
  const std::vector<std::string> later = registered_case_sections();
  for (const std::string& s : later) known.push_back(s);
  top.allow_only(known);
  const std::optional<TomlSection> fem = top.table("fem");
  if (!fem) throw InputError(path.string() + ": no [fem] table (the sidecar of a .fem model)");
  fem->allow_only({"fluid", "gap"});
  Problem& problem = c.problem;
  std::string fluid;
  if (const std::optional<std::string> given = fem->string("fluid")) {
    const LibraryMaterial& m = library.get(*given, fem->where("fluid"));
    if (!m.rheology) fem->fail("fluid", "'" + *given + "' is not an MR fluid of the library");
    fluid = m.magnetic.name;
  }
  std::vector<int> gaps;
  for (const TomlSection& gap : fem->table_array("gap")) {
    gap.allow_only({"label", "block", "kind", "name"});
    const int r = sidecar_region(problem, gap);
    mesh::RegionSeed& seed = problem.geometry.regions[r];
    const std::string label =
        format_text("block label '%s' at (%.6g, %.6g) m (%s)", seed.name.c_str(), seed.seed.r,
                    seed.seed.z, seed.where.c_str());
    if (std::find(gaps.begin(), gaps.end(), r) != gaps.end())
      gap.fail("label", label + " is listed twice");
    const int material = problem.regions[r].material;
    const std::string block = material >= 0 ? problem.materials[material].name : "";
    const LibraryMaterial* m = library.find(block);
    if (!m || !m->rheology) {
      gap.fail(gap.has("label") ? "label" : "block",
               label + ": its block '" + block +
                   "' is not an MR fluid of the material library (a gap's block names its fluid)");
    }
    if (fluid.empty()) fluid = m->magnetic.name;
    problem.materials[material].fluid = true;  // every block of this material is fluid
    if (normalised_material_name(m->magnetic.name) != normalised_material_name(fluid)) {
      gap.fail("label", label + " holds '" + m->magnetic.name + "'; expected '" + fluid +
                            "': one fluid fills every gap");
    }
    seed.gap = gap.choice_or("kind", kSidecarGapKinds, mesh::GapKind::annular);
    if (const std::optional<std::string> name = gap.string("name")) seed.name = *name;
    gaps.push_back(r);
  }
  move_regions_first(problem, gaps);
  c.fluid = fluid;
  // [solver] order: the element order (FEMM's mesh sizes and boundaries stay the model's own).
  if (const std::optional<TomlSection> solver = top.table("solver")) {
    solver->allow_only({"order"});
    const long long order = solver->integer_or("order", 2);
    if (order != 1 && order != 2) solver->fail("order", "expected 1 or 2");
    problem.order = static_cast<int>(order);
  }
}

std::string femm_sidecar_text(const Case& c, const Problem& closed) {
  std::ostringstream out;
  bool any = false;
  for (const mesh::RegionSeed& seed : closed.geometry.regions)
    any = any || seed.gap != mesh::GapKind::none;
  if (!any) return "";
  out << "# The fluid gaps of the FEMM model beside this file, for rheomag (docs/femm.md): each\n"
         "# [[fem.gap]] is the block label at `label` [m], in flow order.\n"
         "[fem]\nfluid = \""
      << c.fluid << "\"\n";
  for (const mesh::RegionSeed& seed : closed.geometry.regions) {
    if (seed.gap == mesh::GapKind::none || seed.hole) continue;
    out << "\n[[fem.gap]]\nname = \"" << seed.name << "\"\nlabel = ["
        << format_text("%.17g, %.17g", seed.seed.r, seed.seed.z) << "]\nkind = \""
        << kSidecarGapKinds.name(seed.gap) << "\"\n";
  }
  toml::table later;
  for (const std::string& s : registered_case_sections())
    if (const toml::node* node = c.table.get(s)) {
      if (const toml::table* table = node->as_table()) later.insert(s, *table);
      if (const toml::array* array = node->as_array()) later.insert(s, *array);
    }
  if (!later.empty()) out << "\n" << later << "\n";
  return out.str();
}

}  // namespace rheomag::cases
