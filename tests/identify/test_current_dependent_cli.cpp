// 'rheomag fit-family': a LuGre family simulated at two frequencies and two currents is fitted
// through the CLI and predicts a third frequency; bad input exits 2 with a message naming the
// option or file.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "identify/greybox.hpp"
#include "lumped/recording_io.hpp"
#include "tests/cli_run.hpp"

namespace fs = std::filesystem;
using namespace rheomag::lumped;
using namespace rheomag::identify;

namespace {

using rheomag::cli_test::CliRun;

CliRun run_fit_family(const std::string& args) {
  return rheomag::cli_test::run_rheomag("fit-family " + args);
}

/// Writes a noise-free LuGre recording (2 cycles of a 25 mm sine, 200 samples per cycle) at
/// frequency f and current i into `path`.
void write_lugre_recording(const std::string& path, double f, double current) {
  constexpr double kPi = 3.14159265358979323846;
  Recording rec;
  std::vector<double> x, v;
  for (int k = 0; k < 400; ++k) {
    const double t = k / (200.0 * f);
    rec.t.push_back(t);
    x.push_back(0.025 * std::sin(2 * kPi * f * t));
    v.push_back(0.025 * 2 * kPi * f * std::cos(2 * kPi * f * t));
  }
  rec.columns["displacement"] = x;
  rec.columns["velocity"] = v;
  rec.columns["current"] = std::vector<double>(x.size(), current);
  rec.columns["force"] = std::vector<double>(x.size(), 0.0);  // simulate_pheno reads the column
  rec.meta.drive = {"displacement", "velocity", "current"};
  rec.meta.output = "force";
  rec.meta.rig.kind = rheomag::lumped::RigKind::damper;
  GreyboxSetup setup = greybox_setup_for(rec, PhenoKind::lugre);
  setup.settings.eps = 1e-4;
  setup.settings.motion_scale = 0.05;
  rec.columns["force"] =
      simulate_pheno(rec, setup, {40.0, 260.0, 2.0, 1000.0, 90.0, 700.0, 0.4, 0.0});
  write_recording(rec, path);
}

}  // namespace

// A noise-free family: the fit reproduces it, so every RE (paper 001 eq. 10) on the fitted and
// the predicted recordings is below 0.02 (the model's eps/motion scale differ slightly from the
// ones simulated with, so not exactly 0). JSON carries model, params, train and prediction.
TEST(FitFamilyCli, FitsAFamilyAndPredictsAThirdFrequency) {
  const fs::path dir =
      fs::temp_directory_path() / ("rheomag_fit_family_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::string training, prediction;
  for (double f : {0.1, 0.25})
    for (double i : {0.0, 1.0}) {
      const std::string p = (dir / ("f" + std::to_string(f) + "_i" + std::to_string(i) + ".csv"));
      write_lugre_recording(p, f, i);
      training += " " + p;
    }
  prediction = (dir / "predict.csv").string();
  write_lugre_recording(prediction, 0.5, 0.5);
  const CliRun r = run_fit_family(training + " --model lugre --decimation 2 --predict " +
                                  prediction + " --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["model"], "lugre");
  EXPECT_TRUE(j["params"].contains("stiffness_per_field"));
  ASSERT_EQ(j["train"].size(), 4u);
  ASSERT_EQ(j["prediction"].size(), 1u);
  EXPECT_NEAR(j["prediction"][0]["field"].get<double>(), 0.5, 1e-12);
  EXPECT_LT(j["prediction"][0]["re"].get<double>(), 0.02);
  for (const auto& m : j["train"]) EXPECT_LT(m["re"].get<double>(), 0.02);
  // Every recording's residual by regime: three regimes whose time and energy shares add to 100.
  for (const auto& m : j["prediction"]) {
    double time = 0.0, energy = 0.0;
    for (const char* regime : {"transition", "positive", "negative"}) {
      ASSERT_TRUE(m["regimes"].contains(regime)) << m.dump();
      time += m["regimes"][regime]["time_percent"].get<double>();
      energy += m["regimes"][regime]["energy_percent"].get<double>();
      EXPECT_GE(m["regimes"][regime]["rms"].get<double>(), 0.0);
    }
    EXPECT_NEAR(time, 100.0, 1e-9);
    EXPECT_NEAR(energy, 100.0, 1e-9);
  }
  const CliRun text = run_fit_family(training + " --model lugre --decimation 2 --predict " +
                                     prediction + " --quiet");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("residual by regime"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("reversals: from each reversal"), std::string::npos) << text.out;

  const CliRun bad_model = run_fit_family(training + " --model arx:2,2,1");
  EXPECT_EQ(bad_model.code, 2);
  EXPECT_NE(bad_model.err.find("--model"), std::string::npos) << bad_model.err;
  const CliRun missing = run_fit_family((dir / "absent.csv").string() + " --model lugre");
  EXPECT_EQ(missing.code, 2);
  EXPECT_NE(missing.err.find("absent.csv"), std::string::npos) << missing.err;
  fs::remove_all(dir);
}
