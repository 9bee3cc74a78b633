// The fitted-model JSON: written by `rheomag fit`/`fit-family --json`, read back by
// read_fit_model_json, and run again: the read-back model's simulation equals the fitted one's
// bit for bit (nlohmann writes doubles with 17 significant digits); every malformed document is
// refused naming the file, the key and what was expected.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <span>
#include <string>

#include "core/error.hpp"
#include "identify/fit_model_json.hpp"
#include "identify/greybox.hpp"
#include "identify/valve_chain_fit.hpp"
#include "lumped/metrics.hpp"

using namespace rheomag::lumped;
using namespace rheomag::identify;
namespace fs = std::filesystem;

namespace {

/// A damper recording: velocity sine of amplitude `v0`, Bingham-like force with a current step.
Recording damper_recording(double v0) {
  Recording rec;
  rec.csv_path = "rec.csv";
  rec.meta.drive = {"velocity", "current"};
  rec.meta.output = "force";
  rec.meta.rig.kind = RigKind::damper;
  std::vector<double> v, i, f;
  for (int k = 0; k < 400; ++k) {
    const double t = k * 0.005;
    rec.t.push_back(t);
    v.push_back(v0 * std::sin(2 * M_PI * 2 * t));
    i.push_back(k < 200 ? 0.2 : 0.8);
    f.push_back((300 + 900 * i.back()) * std::tanh(v.back() / 0.01) + 2000 * v.back());
  }
  rec.columns = {{"velocity", v}, {"current", i}, {"force", f}};
  return rec;
}

/// A valve-chain model over a small hand-made static map (no FE case needed to store one).
ValveChainFit chain_model() {
  auto map = std::make_shared<ChainMapTable>();
  map->case_file = "valve.toml";
  map->current = {0.0, 0.5, 1.0};
  map->flow = {1e-7, 1e-6, 1e-5};
  map->yield = {1e4, 1.1e4, 1.2e4, 3e4, 3.3e4, 3.6e4, 6e4, 6.6e4, 7.2e4};
  map->viscous_resistance = 2e8;
  ValveChainFit fit;
  fit.setup.map = map;
  fit.setup.motion_column = "flow";
  fit.setup.field_column = "current";
  fit.setup.output_column = "pressure";
  fit.setup.eps_flow = 1e-8;
  fit.params = valve_chain_parameters({0.93, 1.2, 0.02, 0.0}, /*compliant=*/false);
  return fit;
}

Recording valve_recording() {
  Recording rec;
  rec.csv_path = "valve.csv";
  rec.meta.drive = {"flow", "current"};
  rec.meta.output = "pressure";
  std::vector<double> q, i, p;
  for (int k = 0; k < 300; ++k) {
    rec.t.push_back(k * 0.002);
    q.push_back(8e-6 * std::sin(0.05 * k));
    i.push_back(k < 150 ? 0.1 : 0.9);
    p.push_back(5e4 * std::tanh(q.back() / 1e-7));
  }
  rec.columns = {{"flow", q}, {"current", i}, {"pressure", p}};
  return rec;
}

/// A fresh directory `dir` holding `rec` as rec.csv with its sidecar rec.toml (a damper).
void write_recording_files(const Recording& rec, const fs::path& dir) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream csv(dir / "rec.csv");
  csv.precision(17);
  csv << "t,velocity,current,force\n";
  for (std::size_t k = 0; k < rec.t.size(); ++k)
    csv << rec.t[k] << ',' << rec.columns.at("velocity")[k] << ',' << rec.columns.at("current")[k]
        << ',' << rec.columns.at("force")[k] << '\n';
  std::ofstream(dir / "rec.toml") << "[recording]\ndrive = [\"velocity\", \"current\"]\n"
                                     "output = \"force\"\n[rig]\nkind = \"damper\"\n";
}

/// The message of the InputError `parse_fit_model_json(text)` throws ("(none)" if it passes).
std::string refusal(const std::string& text) {
  try {
    parse_fit_model_json(text, "model.json");
  } catch (const rheomag::InputError& e) {
    return e.what();
  }
  return "(none)";
}

}  // namespace

// Grey-box: fit, write, read, simulate on the fitted recording and on another one of the same
// device (other amplitude): identical to simulate_greybox of the fit itself.
TEST(FitModelJson, GreyboxRoundTripSimulatesTheSame) {
  const Recording rec = damper_recording(0.05);
  GreyboxOptions options;
  options.starts = 1;
  options.max_iterations = 20;
  const GreyboxFit fit = fit_greybox(rec, "bingham", options);
  const std::string text = fit_model_json(fit, rec.meta).dump(2);
  const FitModel back = parse_fit_model_json(text, "model.json");
  EXPECT_EQ(back.model, "bingham");
  ASSERT_TRUE(back.rig.has_value());
  EXPECT_EQ(*back.rig, RigKind::damper);
  EXPECT_EQ(back.drive, rec.meta.drive);
  ASSERT_TRUE(back.greybox.has_value());
  ASSERT_EQ(back.greybox->params.size(), fit.params.size());
  for (std::size_t k = 0; k < fit.params.size(); ++k) {
    EXPECT_EQ(back.greybox->params[k].value, fit.params[k].value) << fit.params[k].name;
    EXPECT_EQ(back.greybox->params[k].unit, fit.params[k].unit) << fit.params[k].name;
  }
  for (double v0 : {0.05, 0.08}) {
    const Recording other = damper_recording(v0);
    EXPECT_EQ(simulate_fit_model(other, back), simulate_greybox(other, fit)) << v0;
  }
}

// A fit whose velocity is read 7.5 ms later (GreyboxOptions::motion_lead) writes the lead
// (setup.motion_lead_s), reads it back, and the read-back model simulates bit for bit as the fit;
// the lead is not a no-op (the same parameters without it simulate otherwise).
TEST(FitModelJson, GreyboxRoundTripCarriesTheMotionLead) {
  const Recording rec = damper_recording(0.05);
  GreyboxOptions options;
  options.starts = 1;
  options.max_iterations = 20;
  options.motion_lead = 7.5e-3;
  const GreyboxFit fit = fit_greybox(rec, "bingham", options);
  EXPECT_EQ(fit.setup.motion_lead, 7.5e-3);
  const nlohmann::json j = fit_model_json(fit, rec.meta);
  EXPECT_EQ(j.at("setup").at("motion_lead_s").get<double>(), 7.5e-3);
  const FitModel back = parse_fit_model_json(j.dump(2), "model.json");
  ASSERT_TRUE(back.greybox.has_value());
  EXPECT_EQ(back.greybox->setup.motion_lead, 7.5e-3);
  EXPECT_EQ(simulate_fit_model(rec, back), simulate_greybox(rec, fit));
  GreyboxFit unled = fit;
  unled.setup.motion_lead = 0.0;
  EXPECT_NE(simulate_greybox(rec, unled), simulate_greybox(rec, fit));
  // A lead outside +-1 s is refused with its key.
  nlohmann::json bad = j;
  bad["setup"]["motion_lead_s"] = 2.0;
  EXPECT_NE(refusal(bad.dump()).find("motion_lead_s"), std::string::npos) << refusal(bad.dump());
}

// A damper model written before the model had field_saturation and output_smoothing (15
// parameters) reads back with both held at 0 (field linear in the current, output not smoothed)
// and simulates bit for bit as the same parameters with explicit zeros; a Bingham model written
// before output_smoothing (6 parameters) likewise.
TEST(FitModelJson, ModelsWithoutLaterParametersReadAsBefore) {
  const Recording rec = damper_recording(0.05);
  for (const PhenoKind kind : {PhenoKind::damper, PhenoKind::bingham}) {
    GreyboxFit fit;
    fit.model = pheno_name(kind);
    fit.setup = greybox_setup_for(rec, kind);
    fit.setup.settings.eps = 1e-6;
    fit.setup.settings.motion_scale = 0.05;
    fit.setup.settings.output_scale = 1000.0;
    const std::vector<double> values =
        kind == PhenoKind::damper
            ? std::vector<double>{200.0, 300.0, 0.0,  2000.0, 0.0, 1.0,  1e12, 1e6, 0.0,
                                  0.0,   0.0,   1e-3, 0.0,    0.0, 0.01, 0.0,  0.0, 0.0}
            : std::vector<double>{200.0, 300.0, 2000.0, 0.0, 0.01, 0.0, 0.0};
    ASSERT_EQ(values.size(), pheno_params(kind).size());
    for (std::size_t k = 0; k < values.size(); ++k) {
      FittedParameter p;
      p.name = pheno_params(kind)[k].name;
      p.unit = pheno_params(kind)[k].unit;
      p.value = values[k];
      fit.params.push_back(p);
    }
    nlohmann::json j = fit_model_json(fit, rec.meta);
    nlohmann::json& list = j["parameters"];
    for (std::size_t k = list.size(); k-- > 0;)  // as written before they existed
      if (list[k]["name"] == "output_smoothing" || list[k]["name"] == "field_saturation" ||
          list[k]["name"] == "seal_friction_per_field")
        list.erase(k);
    ASSERT_EQ(list.size(), values.size() - (kind == PhenoKind::damper ? 3 : 1));
    const FitModel back = parse_fit_model_json(j.dump(), "old_model.json");
    ASSERT_TRUE(back.greybox.has_value());
    ASSERT_EQ(back.greybox->params.size(), values.size());
    for (const char* name : {"output_smoothing", "field_saturation", "seal_friction_per_field"}) {
      const int k = pheno_param_index(kind, name);
      if (k < 0) continue;
      const FittedParameter& p = back.greybox->params[static_cast<std::size_t>(k)];
      EXPECT_EQ(p.name, name);
      EXPECT_EQ(p.value, 0.0) << name;
      EXPECT_TRUE(p.fixed) << name;
    }
    EXPECT_EQ(simulate_fit_model(rec, back), simulate_pheno(rec, fit.setup, values));
  }
}

// Valve-chain: the static map travels with the model (grid, yield table, viscous resistance).
TEST(FitModelJson, ValveChainRoundTripCarriesTheStaticMap) {
  const ValveChainFit fit = chain_model();
  RecordingMeta meta;
  meta.drive = {"flow", "current"};
  meta.output = "pressure";
  const FitModel back = parse_fit_model_json(fit_model_json(fit, meta).dump(), "model.json");
  ASSERT_TRUE(back.valve_chain.has_value());
  EXPECT_FALSE(back.rig.has_value());
  EXPECT_EQ(back.valve_chain->setup.map->yield, fit.setup.map->yield);
  EXPECT_EQ(back.valve_chain->setup.map->case_file, "valve.toml");
  const Recording rec = valve_recording();
  const std::vector<double> expected = simulate_valve_chain(rec, fit);
  EXPECT_EQ(simulate_fit_model(rec, back), expected);
  EXPECT_GT(std::abs(expected[200]), 1e4);  // the map is used: a real pressure drop
}

// Each malformed document is refused with the file, the key and what was expected.
TEST(FitModelJson, MalformedDocumentsNamed) {
  const Recording rec = damper_recording(0.05);
  GreyboxFit fit;
  fit.model = "bingham";
  fit.setup = greybox_setup_for(rec, PhenoKind::bingham);
  for (const PhenoParam& p : pheno_params(PhenoKind::bingham))
    fit.params.push_back(
        {p.name, p.unit, p.name == "output_smoothing" ? 0.1 : 1.0, std::nullopt, false, false});
  const nlohmann::json good = fit_model_json(fit, rec.meta);
  EXPECT_EQ(refusal(good.dump()), "(none)");
  auto with = [&](const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json j = good;
    edit(j);
    return refusal(j.dump());
  };
  EXPECT_EQ(refusal("{\"format\": "),
            "model.json: not a JSON document (byte 12); expected the output of 'rheomag fit "
            "--json' or 'fit-family --json'");
  EXPECT_EQ(refusal("{\"format\": 1e999}"),  // found by lumped.ReaderFuzz.FitModelJson
            "model.json: not a readable JSON document: number overflow parsing '1e999'");
  EXPECT_EQ(refusal("[1, 2]"),
            "model.json: expected a JSON object (the output of 'rheomag fit --json')");
  EXPECT_EQ(with([](auto& j) { j.erase("format"); }), "model.json: key 'format' is missing");
  EXPECT_EQ(with([](auto& j) { j["format"] = "rheomag-fit-model/9"; }),
            "model.json: key 'format': expected \"rheomag-fit-model/1\", got "
            "\"rheomag-fit-model/9\"");
  EXPECT_EQ(with([](auto& j) {
              j["kind"] = "black-box";
              j["model"] = "arx:2,2,1";
            }),
            "model.json: key 'kind': model 'arx:2,2,1' is a black-box model: its JSON lists its "
            "parameters for reading, but only grey-box and valve-chain models can be read back "
            "and run");
  EXPECT_EQ(with([](auto& j) { j["model"] = "binghma"; }),
            "model.json: key 'model': expected a grey-box model (bingham, lugre, bouc-wen, "
            "maxwell, dahl, bi-viscous, tanh, damper), got \"binghma\"");
  EXPECT_EQ(with([](auto& j) { j["rig"] = "pump"; }),
            "model.json: key 'rig': expected \"constant_velocity_pump\", \"bypass_cylinder\", "
            "\"damper\" or \"coil_bench\", got \"pump\"");
  EXPECT_EQ(with([](auto& j) { j["drive"] = "velocity"; }),
            "model.json: key 'drive': expected an array, got a string (\"velocity\")");
  EXPECT_EQ(with([](auto& j) { j["setup"]["settings"]["eps"] = -1.0; }),
            "model.json: key 'setup.settings.eps': expected a positive number, got -1");
  EXPECT_EQ(with([](auto& j) { j["setup"]["orientation"] = 0.5; }),
            "model.json: key 'setup.orientation': expected 1 or -1, got 0.500000");
  EXPECT_EQ(with([](auto& j) { j["parameters"][1]["name"] = "c1"; }),
            "model.json: key 'parameters[1].name': expected \"" +
                pheno_params(PhenoKind::bingham)[1].name +
                "\" (parameter 2 of bingham), got "
                "\"c1\"");
  EXPECT_EQ(with([](auto& j) { j["parameters"][0]["value"] = "3"; }),
            "model.json: key 'parameters[0].value': expected a finite number, got a string "
            "(\"3\")");
  EXPECT_EQ(with([](auto& j) { j["parameters"].erase(0); }),
            "model.json: key 'parameters': model bingham has " +
                std::to_string(pheno_params(PhenoKind::bingham).size()) + " parameters, got " +
                std::to_string(pheno_params(PhenoKind::bingham).size() - 1));

  // Issue 36: parameters outside their physical domain (the fit's scale-free bounds) were read
  // and simulated (viscous = -1e308 gave -1.26e307 N with exit 0).
  EXPECT_EQ(with([](auto& j) { j["parameters"][2]["value"] = -1e308; }),
            "model.json: key 'parameters[2].value': parameter viscous of bingham: expected a "
            "number >= 0, got -1e+308 (the bound a fit of bingham keeps it in)");
  EXPECT_EQ(with([](auto& j) { j["parameters"][4]["value"] = -0.1; }),
            "model.json: key 'parameters[4].value': parameter transition of bingham: expected a "
            "positive number, got -0.1 (the bound a fit of bingham keeps it in)");
  EXPECT_EQ(with([](auto& j) { j["parameters"][6]["value"] = 5; }),
            "model.json: key 'parameters[6].value': parameter output_smoothing of bingham: "
            "expected a number in [0, 0.25], got 5 (the bound a fit of bingham keeps it in)");
  // A fit that ended on a bound comes back with the rounding of its scaled parameter: read.
  EXPECT_EQ(with([](auto& j) { j["parameters"][6]["value"] = 0.25000000000000006; }), "(none)");

  RecordingMeta meta;
  meta.drive = {"flow", "current"};
  meta.output = "pressure";
  const nlohmann::json chain = fit_model_json(chain_model(), meta);
  nlohmann::json j = chain;
  j["parameters"][0]["value"] = -2.0;
  EXPECT_EQ(refusal(j.dump()),
            "model.json: key 'parameters[0].value': parameter yield_scale of valve-chain: "
            "expected a number in [0.01, 100], got -2 (the bound a fit of valve-chain keeps it "
            "in)");
  j = chain;
  j["static_map"]["flow"][2] = 1e-7;
  EXPECT_EQ(refusal(j.dump()),
            "model.json: key 'static_map.flow[2]': expected a value above the previous one "
            "(0.000001): the grid must increase strictly");
  j = chain;
  j["static_map"]["yield"].erase(0);
  EXPECT_EQ(refusal(j.dump()),
            "model.json: key 'static_map.yield': expected 9 values (current x flow), got 8");
  j = chain;
  j["static_map"]["current"][0] = 0.1;
  EXPECT_EQ(refusal(j.dump()),
            "model.json: key 'static_map.current[0]': expected 0 (the grid starts at no current)");
}

// A model read back must fit the recording it is run on: other output column -> InputError.
TEST(FitModelJson, OtherOutputColumnRefused) {
  const FitModel back = [] {
    RecordingMeta meta;
    meta.drive = {"flow", "current"};
    meta.output = "pressure";
    return parse_fit_model_json(fit_model_json(chain_model(), meta).dump(), "model.json");
  }();
  Recording rec = damper_recording(0.05);
  try {
    simulate_fit_model(rec, back);
    ADD_FAILURE() << "no error";
  } catch (const rheomag::InputError& e) {
    EXPECT_STREQ(e.what(),
                 "rec.csv: output column 'force', the valve-chain model was fitted to 'pressure'");
  }
}

// End to end: `rheomag fit --json` printed to a file, read back, run on the recording: its FIT
// equals the FIT the command printed (same model, same simulation; 1e-9 %).
TEST(FitModelJson, CliOutputReadsBackAndReproducesItsFit) {
  const fs::path dir = fs::temp_directory_path() / "rheomag_fit_model_json";
  const Recording rec = damper_recording(0.05);
  write_recording_files(rec, dir);
  const std::string command = "cd '" + dir.string() + "' && '" + RHEOMAG_BINARY +
                              "' fit rec.csv --model bingham --json > model.json";
  ASSERT_EQ(std::system(command.c_str()), 0);
  const FitModel back = read_fit_model_json(dir / "model.json");
  std::ifstream in(dir / "model.json");
  const nlohmann::json printed = nlohmann::json::parse(in);
  Recording again = rec;
  again.csv_path = (dir / "rec.csv").string();
  const std::vector<double> y = simulate_fit_model(again, back);
  const Metrics m = compute_metrics(std::span<const double>(rec.columns.at("force")),
                                    std::span<const double>(y), SampleRange{0, y.size()});
  EXPECT_NEAR(m.fit_percent, printed["train"]["fit_percent"].get<double>(), 1e-9);
  fs::remove_all(dir);
}

// `rheomag fit --json > model.out` (or model.JSON, or no extension): simulate chose its reader by
// the exact extension ".json" and read such a model as a TOML rig spec, refusing it with "Error
// while parsing root table: expected keys, ... saw '{'". A JSON object is recognised by its '{'.
TEST(FitModelJson, SimulateReadsAModelSavedUnderAnyName) {
  const fs::path dir = fs::temp_directory_path() / "rheomag_fit_model_any_name";
  write_recording_files(damper_recording(0.05), dir);
  const std::string cd = "cd '" + dir.string() + "' && '" + RHEOMAG_BINARY + "' ";
  ASSERT_EQ(std::system((cd + "fit rec.csv --model bingham --json > model.out").c_str()), 0);
  fs::copy_file(dir / "model.out", dir / "model.JSON");
  fs::copy_file(dir / "model.out", dir / "model");
  for (const std::string name : {"model.out", "model.JSON", "model"}) {
    const std::string run =
        cd + "simulate " + name + " --input rec.csv --out pred.csv > /dev/null 2> err.txt";
    EXPECT_EQ(std::system(run.c_str()), 0) << name;
    std::ifstream err(dir / "err.txt");
    EXPECT_EQ(std::string(std::istreambuf_iterator<char>(err), {}), "") << name;
  }
  fs::remove_all(dir);
}
