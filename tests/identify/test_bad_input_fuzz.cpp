// Reader robustness of recordings and fitted models: truncated and mutated recording CSVs, TOML
// sidecars and fitted-model JSON documents end only in a parse or an InputError - never another
// exception, a crash or undefined behaviour. CTest also runs this file under AddressSanitizer +
// UBSan (identify.reader_fuzz_asan, tests/identify/CMakeLists.txt). Deterministic (fixed seeds),
// bounded: about 5300 inputs.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <sstream>
#include <string>

#include "identify/fit_model_json.hpp"
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

/// Fitted-model documents: a Bingham damper model and a valve-chain model with its static map.
std::vector<std::string> fit_model_documents() {
  using namespace rheomag::lumped;
  using namespace rheomag::identify;
  RecordingMeta meta;
  meta.drive = {"velocity", "current"};
  meta.output = "force";
  meta.rig.kind = RigKind::damper;
  GreyboxFit grey;
  grey.model = "bingham";
  grey.setup.motion_column = "velocity";
  grey.setup.field_column = "current";
  grey.setup.output_column = "force";
  for (const PhenoParam& p : pheno_params(PhenoKind::bingham))
    grey.params.push_back(  // in every parameter's domain (output_smoothing in [0, 0.25])
        {p.name, p.unit, p.name == "output_smoothing" ? 0.1 : 1.5, 0.1, false, false});
  ValveChainFit chain;
  auto map = std::make_shared<ChainMapTable>();
  map->case_file = "valve.toml";
  map->current = {0.0, 1.0};
  map->flow = {1e-7, 1e-5};
  map->yield = {1e4, 1.2e4, 6e4, 7.2e4};
  map->viscous_resistance = 2e8;
  chain.setup.map = map;
  chain.setup.motion_column = "velocity";
  chain.setup.field_column = "current";
  chain.setup.output_column = "force";
  chain.setup.piston_area = 1e-3;
  for (const char* name : {"yield_scale", "viscous_scale", "field_time_constant",
                           "hydraulic_capacitance"})  // the names the fit writes
    chain.params.push_back({name, "1", 0.5, std::nullopt, false, false});
  return {fit_model_json(grey, meta).dump(2), fit_model_json(chain, meta).dump(2)};
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

TEST(ReaderFuzz, FitModelJson) {
  unsigned seed = 41;
  for (const std::string& text : fit_model_documents()) {
    rheomag::identify::parse_fit_model_json(text, "model.json");  // the seed itself is valid
    expect_only_input_errors(mutants(text, seed++, 1000), [](const std::string& t) {
      rheomag::identify::parse_fit_model_json(t, "model.json");
    });
  }
}
