// Reader robustness of sweep specs: truncated and mutated sweep files end only in a parse or an
// InputError - never another exception, a crash or undefined behaviour. CTest also runs this
// file under AddressSanitizer + UBSan (sweep.sweep_fuzz_asan, tests/sweep/CMakeLists.txt).
// Deterministic (fixed seed), bounded: about 750 inputs, each reading the bundled base case.

#include <gtest/gtest.h>

#include <string>

#include "case/case_sections.hpp"
#include "sweep/spec.hpp"
#include "tests/input_fuzz.hpp"
// Base cases carry [valve]; in the program the valve layer registers it (valve_chain.hpp), and
// this test, which does not use the valve layer, registers it itself.
const bool kValveSectionRegistered = rheomag::cases::register_case_section("valve");

using rheomag::testing::expect_only_input_errors;
using rheomag::testing::mutants;
using rheomag::testing::read;

TEST(ReaderFuzz, SweepSpec) {
  // The bundled example: its base case path is relative to the spec's folder.
  const std::string path =
      std::string(RHEOMAG_SOURCE_DIR) + "/cases/sweeps/annular_gap_current.toml";
  const std::string text = read(path);
  ASSERT_FALSE(text.empty());
  rheomag::sweep::parse_sweep(text, path);
  expect_only_input_errors(mutants(text, 18, 600),
                           [&](const std::string& t) { rheomag::sweep::parse_sweep(t, path); });
}
