// Materials library: TOML material files -> Material (+ raw rheology table).

#include "case/material_library.hpp"

#include <dlfcn.h>

#include <algorithm>
#include <cctype>

#include "core/error.hpp"

#ifndef RHEOMAG_MATERIALS_DIR
#define RHEOMAG_MATERIALS_DIR "cases/materials"
#endif

namespace rheomag::cases {

std::string normalised_material_name(std::string_view name) {
  std::string result;
  for (char c : name) {
    if (c == ' ' || c == '-' || c == '_') continue;
    result.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
  }
  return result;
}

std::vector<BhPoint> checked_bh_table(const std::vector<std::pair<double, double>>& pairs,
                                      const std::string& where) {
  if (pairs.size() < 2)
    throw InputError(where + ": a B-H table needs at least 2 points [B, H], got " +
                     std::to_string(pairs.size()));
  std::vector<BhPoint> table;
  if (pairs.front().first != 0.0 || pairs.front().second != 0.0) table.push_back({0.0, 0.0});
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    const BhPoint p{pairs[i].first, pairs[i].second};
    if (!table.empty() && (p.b <= table.back().b || p.h <= table.back().h))
      throw InputError(where + ": B-H table is not monotone at point " + std::to_string(i + 1) +
                       " [" + format_number(p.b) + ", " + format_number(p.h) +
                       "]: B and H must both increase strictly from (0, 0)");
    table.push_back(p);
  }
  return table;
}

ThermalProperties read_thermal_properties(const TomlSection& section) {
  ThermalProperties t;
  t.conductivity = section.quantity("conductivity", Domain::positive("W/(m K)"));
  t.density = section.quantity("density", Domain::positive("kg/m^3"));
  t.specific_heat = section.quantity("specific_heat", Domain::positive("J/(kg K)"));
  t.source = section.string("source").value_or("");
  return t;
}

LibraryMaterial read_material(const TomlSection& section) {
  section.allow_only({"name", "source", "uncertainty", "mu_r", "mu_r_axes", "bh", "conductivity",
                      "rheology", "thermal"});
  LibraryMaterial result;
  Material& m = result.magnetic;
  m.name = section.required_string("name");
  m.source = section.string("source").value_or("");
  if (section.has("conductivity")) m.conductivity = section.non_negative_or("conductivity", 0.0);
  if (section.has("bh") && section.has("mu_r"))
    section.fail("mu_r", "give either mu_r (linear) or bh (B-H table), not both");
  if (section.has("mu_r_axes") && (section.has("bh") || section.has("mu_r")))
    section.fail("mu_r_axes", "give one of mu_r, mu_r_axes (linear, anisotropic) or bh");
  if (section.has("bh")) {
    m.bh = checked_bh_table(section.pairs("bh"), section.where("bh"));
  } else if (section.has("mu_r_axes")) {
    // A laminated core's permeabilities along r (x) and z (y), e.g. from FEMM's LamType 1 / 2.
    const std::vector<double> mu = section.quantities("mu_r_axes", Domain::positive());
    if (mu.size() != 2)
      section.fail("mu_r_axes", "expected 2 numbers, mu_r along r (x) and along z (y); got " +
                                    std::to_string(mu.size()));
    m.mu_r = mu[0];
    m.mu_r_axes = std::array{mu[0], mu[1]};
  } else {
    m.mu_r = section.positive_or("mu_r", 1.0);
  }
  if (auto rheology = section.table("rheology")) result.rheology = rheology->raw();
  if (auto thermal = section.table("thermal")) {
    thermal->allow_only(kThermalKeys);
    m.thermal = read_thermal_properties(*thermal);
  }
  m.fluid = result.rheology.has_value();
  return result;
}

MaterialLibrary MaterialLibrary::load(const std::filesystem::path& directory) {
  std::error_code error;
  if (!std::filesystem::is_directory(directory, error))
    throw InputError(directory.string() + ": materials directory not found");
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(directory, error))
    if (entry.path().extension() == ".toml") files.push_back(entry.path());
  std::sort(files.begin(), files.end());
  MaterialLibrary library;
  for (const auto& path : files) {
    const toml::table root = parse_toml_file(path.string());
    const TomlSection top(root, "", path.string());
    top.allow_only({"material", "rheology", "thermal"});
    const std::optional<TomlSection> material = top.table("material");
    if (!material) top.fail("material", "missing [material] table");
    LibraryMaterial entry = read_material(*material);
    if (auto rheology = top.table("rheology")) entry.rheology = rheology->raw();
    if (auto thermal = top.table("thermal")) {
      thermal->allow_only(kThermalKeys);
      entry.magnetic.thermal = read_thermal_properties(*thermal);
    }
    entry.magnetic.fluid = entry.rheology.has_value();
    entry.file = path.string();
    if (library.find(entry.magnetic.name))
      throw InputError(material->where("name") + ": material '" + entry.magnetic.name +
                       "' is defined twice in " + directory.string());
    library.add(std::move(entry));
  }
  return library;
}

namespace {

/// The installed materials (share/rheomag/materials beside the lib/ or bin/ folder of the binary
/// holding this code) when they exist, otherwise the source tree's cases/materials.
std::filesystem::path bundled_materials_dir() {
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&bundled_materials_dir), &info) != 0 &&
      info.dli_fname != nullptr) {
    std::error_code ec;
    const std::filesystem::path binary = std::filesystem::canonical(info.dli_fname, ec);
    const std::filesystem::path installed =
        binary.parent_path().parent_path() / "share" / "rheomag" / "materials";
    if (!ec && std::filesystem::is_directory(installed, ec)) return installed;
  }
  return RHEOMAG_MATERIALS_DIR;
}

}  // namespace

const MaterialLibrary& MaterialLibrary::standard() {
  static const MaterialLibrary library = load(bundled_materials_dir());
  return library;
}

void MaterialLibrary::add(LibraryMaterial material) {
  const std::string key = normalised_material_name(material.magnetic.name);
  for (LibraryMaterial& existing : materials_) {
    if (normalised_material_name(existing.magnetic.name) == key) {
      existing = std::move(material);
      return;
    }
  }
  materials_.push_back(std::move(material));
}

const LibraryMaterial* MaterialLibrary::find(std::string_view name) const {
  const std::string key = normalised_material_name(name);
  for (const LibraryMaterial& m : materials_)
    if (normalised_material_name(m.magnetic.name) == key) return &m;
  return nullptr;
}

const LibraryMaterial& MaterialLibrary::get(std::string_view name, const std::string& where) const {
  if (const LibraryMaterial* m = find(name)) return *m;
  std::vector<std::string> all = names();
  std::vector<std::string_view> views(all.begin(), all.end());
  std::string message = where + ": unknown material '" + std::string(name) + "'";
  const std::string suggestion = closest_key(name, views);
  if (!suggestion.empty()) message += "; did you mean '" + suggestion + "'?";
  message += " Known materials:";
  for (const std::string& n : all) message += " '" + n + "'";
  message += " (library or inline [[material]] tables)";
  throw InputError(message);
}

std::vector<std::string> MaterialLibrary::names() const {
  std::vector<std::string> result;
  for (const LibraryMaterial& m : materials_) result.push_back(m.magnetic.name);
  return result;
}

}  // namespace rheomag::cases
