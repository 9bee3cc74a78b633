// Parser robustness: truncated and randomly mutated .fem and .toml inputs must only ever end in
// a successful parse or an InputError - never another exception, a crash or undefined
// behaviour. CTest also runs this file under AddressSanitizer + UBSan
// (case.parser_fuzz_asan, tests/case/CMakeLists.txt). Deterministic: a fixed
// seed, a few thousand inputs.

#include <gtest/gtest.h>

#include <string>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "case/femm_import.hpp"
#include "core/error.hpp"
#include "tests/case/pot_core_magnet.hpp"
#include "tests/input_fuzz.hpp"

// The bundled cases carry sections of later layers ([valve], [optimise]); in the program those
// layers register them, and this test, which links only the layers below, registers them itself.
const bool kLaterSectionsRegistered = rheomag::cases::register_case_section("valve") &&
                                      rheomag::cases::register_case_section("optimise");

using namespace rheomag::cases;

using rheomag::testing::expect_only_input_errors;
using rheomag::testing::mutants;
using rheomag::testing::read;

TEST(ParserFuzz, FemmFile) {
  const std::string text = read(std::string(RHEOMAG_TEST_DATA) + "/pot_core.fem");
  ASSERT_FALSE(text.empty());
  expect_only_input_errors(mutants(text, 2026, 1500),
                           [](const std::string& t) { parse_femm(t, "fuzz.fem"); });
}

TEST(ParserFuzz, TomlGeneralCase) {
  const std::string text = read(std::string(RHEOMAG_TEST_DATA) + "/pot_core_equivalent.toml");
  ASSERT_FALSE(text.empty());
  expect_only_input_errors(mutants(text, 7, 1000),
                           [](const std::string& t) { parse_case(t, "fuzz.toml"); });
}

TEST(ParserFuzz, TomlTemplateCase) {
  const std::string text = read(std::string(RHEOMAG_SOURCE_DIR) + "/cases/meandering_valve.toml");
  ASSERT_FALSE(text.empty());
  expect_only_input_errors(mutants(text, 11, 600),
                           [](const std::string& t) { parse_case(t, "fuzz.toml"); });
}

// The .fem reader on a model with a magnet, a direction expression (muparser) and a point
// property, mutated; and pot_core.fem cut at every byte: only InputErrors, and a cut file that
// is rejected names a line.
TEST(ParserFuzz, FemmMagnetsAndPointsAndEveryCut) {
  std::string text = read(std::string(RHEOMAG_TEST_DATA) + "/pot_core.fem");
  ASSERT_FALSE(text.empty());
  for (std::size_t cut = 0; cut <= text.size(); ++cut) {
    try {
      parse_femm(text.substr(0, cut), "cut.fem");
    } catch (const rheomag::InputError& e) {
      EXPECT_EQ(std::string(e.what()).rfind("cut.fem:", 0), 0u) << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "cut at byte " << cut << " threw a non-InputError: " << e.what();
    }
  }
  text = rheomag::testing::pot_core_with_magnet(text, "theta + 90 * sin(x / 10)");
  parse_femm(text, "magnet.fem");  // the seed itself parses
  expect_only_input_errors(mutants(text, 1212, 1500),
                           [](const std::string& t) { parse_femm(t, "fuzz.fem"); });
}
