// The bundled materials library (cases/materials/*.toml): every file loads, names a source,
// has a valid magnetic description, the steels reproduce the shared CSV data exactly, and the
// MR fluids carry the rheology the fluid link reads (MRC-C1L through its one published point).

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "case/material_library.hpp"
#include "core/error.hpp"

using namespace rheomag::cases;
using ::testing::HasSubstr;

namespace {

/// Linear interpolation in a [x, y] table (the tables are sampled densely enough for a check).
double interpolate(const std::vector<std::pair<double, double>>& table, double x) {
  for (std::size_t i = 1; i < table.size(); ++i)
    if (x <= table[i].first) {
      const double t = (x - table[i - 1].first) / (table[i].first - table[i - 1].first);
      return table[i - 1].second + t * (table[i].second - table[i - 1].second);
    }
  return table.back().second;
}

}  // namespace

TEST(Materials, EveryLibraryMaterialLoadsWithASource) {
  const MaterialLibrary& library = MaterialLibrary::standard();
  const std::vector<std::string> expected{"AISI 1010", "AISI 1018", "Aluminium 1100",
                                          "Copper",    "Air",       "MRF-132DG",
                                          "MRF-140CG", "MRF-122EG", "MRC-C1L"};
  for (const std::string& name : expected) {
    const LibraryMaterial* m = library.find(name);
    ASSERT_NE(m, nullptr) << name;
    EXPECT_FALSE(m->magnetic.source.empty()) << name;
    // B-H tables start at (0, 0) and increase strictly (checked_bh_table ran on load).
    for (std::size_t i = 1; i < m->magnetic.bh.size(); ++i) {
      EXPECT_GT(m->magnetic.bh[i].b, m->magnetic.bh[i - 1].b) << name;
      EXPECT_GT(m->magnetic.bh[i].h, m->magnetic.bh[i - 1].h) << name;
    }
  }
  EXPECT_EQ(library.names().size(), expected.size());
  // Lookup ignores case, spaces, '-' and '_'.
  EXPECT_EQ(library.find("aisi_1010"), library.find("AISI 1010"));
  EXPECT_EQ(library.find("mrf132dg"), library.find("MRF-132DG"));
}

TEST(Materials, SteelCurvesEqualTheSharedData) {
  for (const auto& [name, file] :
       {std::pair{"AISI 1010", "bh_aisi1010_dosa.csv"}, {"AISI 1018", "bh_aisi1018_dosa.csv"}}) {
    std::ifstream in(std::string(RHEOMAG_SHARED_DIR) + "/data/materials/" + file);
    ASSERT_TRUE(in) << file;
    std::vector<BhPoint> csv;
    std::string line;
    while (std::getline(in, line)) {
      if (line.empty() || line[0] == '#' || line[0] == 'H') continue;
      std::istringstream row(line);
      double h = 0, b = 0;
      char comma = 0;
      row >> h >> comma >> b;
      csv.push_back({b, h});
    }
    const auto& bh = MaterialLibrary::standard().find(name)->magnetic.bh;
    ASSERT_EQ(bh.size(), csv.size()) << name;
    // The TOML keeps 6-8 significant digits of the CSV.
    for (std::size_t i = 0; i < bh.size(); ++i) {
      EXPECT_NEAR(bh[i].b, csv[i].b, 1e-6 * std::max(1.0, csv[i].b)) << name << " " << i;
      EXPECT_NEAR(bh[i].h, csv[i].h, 1e-6 * std::max(1.0, csv[i].h)) << name << " " << i;
    }
  }
}

TEST(Materials, FluidsCarryRheology) {
  for (const char* name : {"MRF-132DG", "MRF-140CG", "MRF-122EG", "MRC-C1L"}) {
    const LibraryMaterial* m = MaterialLibrary::standard().find(name);
    ASSERT_TRUE(m && m->rheology) << name;
    const toml::table& r = *m->rheology;
    EXPECT_GT(r["viscosity"].value_or(0.0), 0.0) << name;
    EXPECT_GT(r["density"].value_or(0.0), 1000.0) << name;
    EXPECT_TRUE(r["yield_stress"].is_array()) << name;
    EXPECT_TRUE(r["source"].is_string()) << name;
  }
  // MRC-C1L: the datasheet's one point, 68 kPa at 570 mT, within the interpolation error of
  // the 0.1 T table (< 1 kPa), and eta = 0.106 Pa s (paper 000, Table 2).
  const toml::table& c1l = *MaterialLibrary::standard().find("MRC-C1L")->rheology;
  const TomlSection section(c1l, "rheology", "mrc_c1l.toml");
  EXPECT_NEAR(interpolate(section.pairs("yield_stress"), 0.57), 68e3, 1e3);
  EXPECT_DOUBLE_EQ(c1l["viscosity"].value_or(0.0), 0.106);
  // MRF-132DG datasheet viscosity 0.092 Pa s (LORD DS7015, paper 001 Table 1).
  EXPECT_DOUBLE_EQ(
      MaterialLibrary::standard().find("MRF-132DG")->rheology->at("viscosity").value_or(0.0),
      0.092);
}

TEST(Materials, LibraryErrors) {
  EXPECT_THAT(
      [] {
        try {
          MaterialLibrary::standard().get("MRF-132D", "case.toml:3");
        } catch (const rheomag::InputError& e) {
          return std::string(e.what());
        }
        return std::string("no error");
      }(),
      HasSubstr("case.toml:3: unknown material 'MRF-132D'; did you mean 'MRF-132DG'?"));
  EXPECT_THROW(MaterialLibrary::load("/nonexistent"), rheomag::InputError);
  EXPECT_THROW(checked_bh_table({{0.5, 100}}, "x"), rheomag::InputError);
  EXPECT_THROW(checked_bh_table({{0.5, 100}, {0.5, 200}}, "x"), rheomag::InputError);
  // A table not starting at (0, 0) gets it prepended.
  EXPECT_EQ(checked_bh_table({{0.5, 100}, {1.0, 300}}, "x").size(), 3u);
}
