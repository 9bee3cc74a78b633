// Parser robustness: truncated and randomly mutated .fem and .toml inputs must only ever end in
// a successful parse or an InputError - never another exception, a crash or undefined
// behaviour. CTest also runs this file under AddressSanitizer + UBSan
// (case.parser_fuzz_asan, tests/case/CMakeLists.txt). Deterministic: a fixed
// seed, a few thousand inputs.

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "case/case_file.hpp"
#include "case/case_sections.hpp"
#include "case/femm_import.hpp"
#include "core/error.hpp"
#include "tests/case/pot_core_magnet.hpp"

// The bundled cases carry sections of later layers ([valve], [optimise]); in the program those
// layers register them, and this test, which links only the layers below, registers them itself.
const bool kLaterSectionsRegistered = rheomag::cases::register_case_section("valve") &&
                                      rheomag::cases::register_case_section("optimise");

using namespace rheomag::cases;

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Mutations: truncation, byte replacement, token injection, line deletion and duplication.
std::vector<std::string> mutants(const std::string& text, unsigned seed, int count) {
  std::vector<std::string> out;
  std::mt19937 random(seed);
  const std::vector<std::string> tokens{"nan",
                                        "inf",
                                        "-1",
                                        "0",
                                        "1e999",
                                        "-1e308",
                                        "\"",
                                        "[",
                                        "]",
                                        "<",
                                        ">",
                                        "=",
                                        "\n",
                                        "\r",
                                        "[[region]]",
                                        "999999",
                                        "<BeginBlock>",
                                        "[NumPoints] = 3",
                                        "\t",
                                        "#",
                                        "{",
                                        "}"};
  for (std::size_t cut = 0; cut < text.size(); cut += std::max<std::size_t>(1, text.size() / 150))
    out.push_back(text.substr(0, cut));
  for (int i = 0; i < count; ++i) {
    std::string m = text;
    const int edits = 1 + static_cast<int>(random() % 3);
    for (int e = 0; e < edits && !m.empty(); ++e) {
      const std::size_t at = random() % m.size();
      switch (random() % 4) {
        case 0:
          m[at] = static_cast<char>(random() % 256);
          break;
        case 1:
          m.insert(at, tokens[random() % tokens.size()]);
          break;
        case 2: {  // delete the line containing `at`
          const std::size_t begin = m.rfind('\n', at);
          const std::size_t end = m.find('\n', at);
          m.erase(begin == std::string::npos ? 0 : begin,
                  end == std::string::npos ? std::string::npos : end - begin);
          break;
        }
        default: {  // duplicate the line containing `at`
          const std::size_t begin = m.rfind('\n', at);
          const std::size_t end = m.find('\n', at);
          const std::size_t b = begin == std::string::npos ? 0 : begin;
          m.insert(b, m.substr(b, (end == std::string::npos ? m.size() : end) - b));
          break;
        }
      }
    }
    out.push_back(m);
  }
  return out;
}

/// Runs `parse` on every mutant; counts outcomes; fails on any non-InputError exception.
void expect_only_input_errors(const std::vector<std::string>& inputs,
                              const std::function<void(const std::string&)>& parse) {
  int parsed = 0, rejected = 0;
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    try {
      parse(inputs[i]);
      ++parsed;
    } catch (const rheomag::InputError& e) {
      ++rejected;
      EXPECT_GT(std::string(e.what()).size(), 10u) << "message too short: " << e.what();
    } catch (const std::exception& e) {
      ADD_FAILURE() << "input " << i << " threw a non-InputError: " << e.what() << "\n---\n"
                    << inputs[i].substr(0, 2000);
    }
  }
  // Both outcomes occur: the mutations reach the parser's checks, not just its first line.
  EXPECT_GT(parsed, 0);
  EXPECT_GT(rejected, static_cast<int>(inputs.size()) / 4);
}

}  // namespace

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
