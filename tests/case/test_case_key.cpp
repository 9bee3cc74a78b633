// The key API: a design edit applied to the typed case must give exactly the case that the
// same value written into the case file gives (reference: the file text read by parse_case;
// tolerance: bitwise, the edit converts file units to SI with the same multiplication). Keys
// resolve with template defaults, special keys and suggestions; sections of later layers are
// accepted only once registered.

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case/case_key.hpp"
#include "case/case_sections.hpp"
#include "case/wire_gauge.hpp"
#include "core/error.hpp"

using namespace rheomag::cases;
using testing::HasSubstr;

namespace {

const std::string kBase = R"(
[case]
units = "mm"
fluid = "MRC-C1L"

[geometry]
template = "annular_valve"
max_arc_angle = 5.0
gap_width = 1.0
wire = "AWG 24"
fill_factor = 0.55

[[circuit]]
name = "coil"
current = 1.0
)";

Case base_case() {
  return parse_case(std::string_view(kBase), "base.toml");
}

/// The same case with `line` added to [geometry] (the way a user edits the file).
Case written(const std::string& geometry_line) {
  std::string text = kBase;
  text.replace(text.find("gap_width = 1.0\n"), 16, "gap_width = 1.0\n" + geometry_line + "\n");
  return parse_case(std::string_view(text), "base.toml");
}

void expect_same_geometry(const Case& a, const Case& b) {
  ASSERT_EQ(a.problem.geometry.points.size(), b.problem.geometry.points.size());
  for (std::size_t i = 0; i < a.problem.geometry.points.size(); ++i) {
    EXPECT_EQ(a.problem.geometry.points[i].r, b.problem.geometry.points[i].r) << i;
    EXPECT_EQ(a.problem.geometry.points[i].z, b.problem.geometry.points[i].z) << i;
  }
  ASSERT_EQ(a.problem.regions.size(), b.problem.regions.size());
  for (std::size_t k = 0; k < a.problem.regions.size(); ++k) {
    EXPECT_EQ(a.problem.regions[k].turns, b.problem.regions[k].turns) << k;
    EXPECT_EQ(a.problem.regions[k].material, b.problem.regions[k].material) << k;
  }
}

std::string error_of(const Case& c, const std::string& key) {
  try {
    resolve_case_key(c, key, "sweep.toml:4", "sweep key");
  } catch (const rheomag::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(CaseKey, TemplateEditEqualsTheWrittenCase) {
  const Case base = base_case();
  const CaseKey key = resolve_case_key(base, "geometry.gap_width", "test");
  EXPECT_EQ(key.target, KeyTarget::template_parameter);
  EXPECT_EQ(key.si_per_unit, 1e-3);  // a millimetre case
  const Case edited = with(base, {{key, 1.25}});
  expect_same_geometry(edited, parse_case(std::string_view([] {
                                            std::string t = kBase;
                                            t.replace(t.find("gap_width = 1.0"), 15,
                                                      "gap_width = 1.25");
                                            return t;
                                          }()),
                                          "base.toml"));
  EXPECT_EQ(std::get<double>(case_value(edited, key)), 1.25);
  // The document follows, so the design can be written out and read back as the same case.
  expect_same_geometry(edited, parse_case(std::string_view(case_file_text(edited)), "out.toml"));
  // The base is unchanged.
  EXPECT_EQ(std::get<double>(case_value(base, key)), 1.0);
}

TEST(CaseKey, TemplateDefaultsResolveAndEdit) {
  const Case base = base_case();
  const CaseKey key = resolve_case_key(base, "geometry.pole_length", "test");
  EXPECT_EQ(key.target, KeyTarget::template_parameter);
  EXPECT_DOUBLE_EQ(numeric_case_value(base, key, "test"), 5.0);  // default, file units (mm)
  expect_same_geometry(with(base, {{key, 6.0}}), written("pole_length = 6.0"));
}

TEST(CaseKey, CurrentEditsKeepTheGeometry) {
  const Case base = base_case();
  const CaseKey key = resolve_case_key(base, "circuit.current", "test");  // one circuit: no index
  EXPECT_EQ(key.target, KeyTarget::circuit_current);
  EXPECT_EQ(key.path, (std::vector<std::string>{"circuit", "0", "current"}));
  const std::vector<CaseEdit> edits{{key, 0.25}};
  EXPECT_TRUE(only_currents(edits));
  const Case edited = with(base, edits);
  EXPECT_EQ(edited.problem.circuits[0].current, 0.25);
  expect_same_geometry(edited, base);
}

TEST(CaseKey, WireGaugeIsTypedAndWholeGaugesEqualTheirNames) {
  const Case base = base_case();
  const CaseKey key = resolve_case_key(base, kWireGaugeKey, "test");
  EXPECT_EQ(key.target, KeyTarget::wire_gauge);
  EXPECT_DOUBLE_EQ(numeric_case_value(base, key, "test"), 24.0);
  // A whole gauge is exactly the case written with that gauge (turns from the window).
  expect_same_geometry(with(base, {{key, 26.0}}), [] {
    std::string t = kBase;
    t.replace(t.find("AWG 24"), 6, "AWG 26");
    return parse_case(std::string_view(t), "base.toml");
  }());
  // A real gauge uses the ASTM B258 formula between the whole gauges (1e-15: same formula).
  const Case relaxed = with(base, {{key, 24.5}});
  EXPECT_EQ(relaxed.input.winding.wire_diameter, awg_diameter_relaxed(24.5));
  EXPECT_NEAR(awg_diameter_relaxed(24.0), awg_diameter(24), 1e-15);
  EXPECT_LT(relaxed.input.winding.wire_diameter, awg_diameter(24));
  EXPECT_GT(relaxed.input.winding.wire_diameter, awg_diameter(25));
  EXPECT_EQ(wire_text(24.0), "AWG 24");
  EXPECT_EQ(wire_text(-1.0), "AWG 00");
}

TEST(CaseKey, FluidSetsTheCaseFluidAndTheGapMaterialTogether) {
  const Case base = base_case();
  const Case edited = with(base, {{resolve_case_key(base, "fluid", "test"), "MRF-140CG"}});
  EXPECT_EQ(edited.fluid, "MRF-140CG");
  EXPECT_EQ(edited.input.template_values.text("fluid_material"), "MRF-140CG");
}

TEST(CaseKey, OtherDocumentValuesAreReadAgain) {
  const Case base = base_case();
  const CaseKey key = resolve_case_key(base, "geometry.max_arc_angle", "test");
  EXPECT_EQ(key.target, KeyTarget::document);
  const Case edited = with(base, {{key, 10.0}});
  EXPECT_EQ(edited.table["geometry"]["max_arc_angle"].value_or(0.0), 10.0);
  expect_same_geometry(edited, base);  // the template has no arcs
}

TEST(CaseKey, UnknownKeysSuggestTheClosest) {
  const Case base = base_case();
  EXPECT_THAT(error_of(base, "geometry.gap_widht"),
              HasSubstr("sweep.toml:4: sweep key 'geometry.gap_widht' does not exist in the case; "
                        "did you mean 'geometry.gap_width'?"));
  EXPECT_THAT(error_of(base, "geometry"), HasSubstr("is a table, not a value"));
  EXPECT_THAT(error_of(base, "circuit.2.current"), HasSubstr("indexes item 2 of a list of 1"));
  EXPECT_THAT(error_of(base, "geometry..gap"), HasSubstr("has an empty component"));
}

// A user's sweep or optimise file with an index beyond any list (20 digits) or a negative one:
// before, std::stoul's out_of_range escaped as "internal error: stoul" (exit 1).
TEST(CaseKey, HugeAndNegativeIndicesAreInputErrors) {
  const Case base = base_case();
  EXPECT_THAT(error_of(base, "circuit.99999999999999999999.current"),
              HasSubstr("sweep.toml:4: sweep key 'circuit.99999999999999999999.current' indexes "
                        "item 99999999999999999999 of a list of 1"));
  EXPECT_THAT(error_of(base, "circuit[99999999999999999999].current"),
              HasSubstr("indexes item 99999999999999999999 of a list of 1"));
  EXPECT_THAT(error_of(base, "circuit[-1].current"),
              HasSubstr("sweep key 'circuit[-1].current' has the negative index -1; expected an "
                        "index from 0 to 0"));
}

TEST(CaseKey, TemplatesDeclareTheirWalls) {
  EXPECT_EQ(find_template("annular_valve")->walls(),
            (std::vector<std::string>{"pole_length", "disk_thickness"}));
  EXPECT_EQ(find_template("meandering_valve")->walls(),
            (std::vector<std::string>{"lip_thickness", "plate_thickness", "shell_thickness"}));
  for (const ValveTemplate& t : valve_templates())
    for (const TemplateParameter& p : t.parameters)
      EXPECT_EQ(p.unit(), p.kind == ParameterKind::length  ? "m"
                          : p.kind == ParameterKind::count ? "1"
                                                           : "")
          << t.name << "." << p.key;
}

TEST(CaseSections, LaterLayersRegisterTheirTables) {
  const std::string text = std::string(kBase) + "\n[dampr]\nstroke = 0.02\n";
  try {
    parse_case(std::string_view(text), "case.toml");
    FAIL() << "an unregistered table must be refused";
  } catch (const rheomag::InputError& e) {
    EXPECT_THAT(std::string(e.what()), HasSubstr("unknown key 'dampr'"));
  }
  register_case_section("dampr");
  EXPECT_NO_THROW(parse_case(std::string_view(text), "case.toml"));
  const auto names = registered_case_sections();
  EXPECT_NE(std::find(names.begin(), names.end(), "dampr"), names.end());
}
