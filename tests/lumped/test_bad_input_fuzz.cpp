// Reader robustness of recordings: truncated and mutated recording CSVs and TOML sidecars end
// only in a parse or an InputError - never another exception, a crash or undefined behaviour.
// CTest also runs this file under AddressSanitizer + UBSan (lumped.reader_fuzz_asan,
// tests/lumped/CMakeLists.txt). Deterministic (fixed seeds), bounded: about 3300 inputs.

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>
#include <string>

#include "lumped/recording_io.hpp"
#include "tests/input_fuzz.hpp"

using rheomag::testing::expect_only_input_errors;
using rheomag::testing::mutants;
using rheomag::testing::read;

namespace {

/// A small valid recording CSV: a comment, a header, 60 samples of a damper-like signal.
std::string recording_csv() {
  std::ostringstream csv;
  csv << "# fuzz seed\nt,velocity,current,force\n";
  for (int k = 0; k < 60; ++k)
    csv << k * 0.005 << ',' << 0.05 * std::sin(0.2 * k) << ',' << (k < 30 ? 0.0 : 0.5) << ','
        << 400.0 * std::tanh(std::sin(0.2 * k)) << '\n';
  return csv.str();
}

}  // namespace

TEST(ReaderFuzz, RecordingCsv) {
  const std::string text = recording_csv();
  rheomag::lumped::parse_csv_samples(text, "fuzz.csv");  // the seed itself is valid
  expect_only_input_errors(mutants(text, 18, 1500), [](const std::string& t) {
    rheomag::lumped::parse_csv_samples(t, "fuzz.csv");
  });
}

TEST(ReaderFuzz, Sidecars) {
  for (const char* name : {"mrdamper.toml", "dyke1996.toml", "utfsm_damper.toml"}) {
    const std::string text = read(std::string(RHEOMAG_TEST_DATA) + "/diagnosis/" + name);
    ASSERT_FALSE(text.empty()) << name;
    rheomag::lumped::parse_sidecar(text, name);
    expect_only_input_errors(mutants(text, 29, 600), [&](const std::string& t) {
      rheomag::lumped::parse_sidecar(t, name);
    });
  }
}
