// 'rheomag fit-family': bad input (mixed rig kinds, mixed drive columns, one current only for a
// current-dependent model, an unknown model) exits 2 naming the file or option; --cross-validate
// predicts each training recording from the others; --report writes a self-contained HTML page
// that renders in headless Chromium.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/html_text.hpp"
#include "identify/fit_model_json.hpp"
#include "identify/greybox.hpp"
#include "lumped/metrics.hpp"
#include "lumped/recording_io.hpp"
#include "tests/cli_run.hpp"

namespace fs = std::filesystem;
using namespace rheomag::lumped;
using namespace rheomag::identify;

namespace {

using rheomag::cli_test::CliRun;

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

CliRun run_fit_family(const std::string& args) {
  return rheomag::cli_test::run_rheomag("fit-family " + args);
}

/// A noise-free Bingham damper recording (2 cycles of a 20 mm sine at 0.5 Hz, 200 samples per
/// cycle) at `current`; `kind` and `drive_current` vary the sidecar for the bad-input cases.
std::string write_recording_at(const fs::path& dir, const std::string& name, double current,
                               RigKind kind = RigKind::damper, bool drive_current = true,
                               double stroke = 0.02) {
  constexpr double kPi = 3.14159265358979323846;
  Recording rec;
  std::vector<double> x, v;
  for (int k = 0; k < 400; ++k) {
    const double t = k / 200.0 / 0.5;
    rec.t.push_back(t);
    x.push_back(stroke * std::sin(kPi * t));
    v.push_back(stroke * kPi * std::cos(kPi * t));
  }
  rec.columns["displacement"] = x;
  rec.columns["velocity"] = v;
  rec.columns["current"] = std::vector<double>(x.size(), current);
  rec.columns["force"] = std::vector<double>(x.size(), 0.0);
  rec.meta.drive = {"displacement", "velocity"};
  if (drive_current) rec.meta.drive.push_back("current");
  rec.meta.output = "force";
  rec.meta.rig.kind = kind;
  GreyboxSetup setup = greybox_setup_for(rec, PhenoKind::bingham);
  setup.settings.eps = 1e-4;
  rec.columns["force"] = simulate_pheno(rec, setup, {100.0, 800.0, 2000.0, 5000.0, 0.005, 0.0});
  const fs::path path = dir / name;
  write_recording(rec, path.string());
  return path.string();
}

fs::path fresh_dir(const std::string& tag) {
  const fs::path dir =
      fs::temp_directory_path() / ("rheomag_family_" + tag + "_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

}  // namespace

TEST(FitFamilyCli, RejectsMixedRigKindsNamingTheFile) {
  const fs::path dir = fresh_dir("rig");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "b.csv", 1.0, RigKind::bypass_cylinder);
  const CliRun r = run_fit_family(a + " " + b + " --model bingham");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("b.csv"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("bypass_cylinder"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(FitFamilyCli, RejectsMixedDriveColumnsNamingTheFile) {
  const fs::path dir = fresh_dir("drive");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "nocurrent.csv", 1.0, RigKind::damper, false);
  const CliRun r = run_fit_family(a + " --predict " + b + " --model bingham");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("nocurrent.csv"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(FitFamilyCli, RejectsOneCurrentOnlyForACurrentDependentModel) {
  const fs::path dir = fresh_dir("one");
  const std::string a = write_recording_at(dir, "a.csv", 0.5);
  const std::string b = write_recording_at(dir, "b.csv", 0.5);
  const CliRun r = run_fit_family(a + " " + b + " --model damper");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--model damper"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("two or more field levels"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

TEST(FitFamilyCli, RejectsAnUnknownModelListingTheKnownOnes) {
  const fs::path dir = fresh_dir("unknown");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const CliRun r = run_fit_family(a + " --model spring");
  EXPECT_EQ(r.code, 2);
  EXPECT_NE(r.err.find("--model"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("damper"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

// --viscosity-nuisance takes LO:HI with 0 < LO <= 1 <= HI <= 100; anything else exits 2 naming
// the option and what it expects, before any fit.
TEST(FitFamilyCli, RejectsBadViscosityNuisanceBounds) {
  const fs::path dir = fresh_dir("nuisance");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "b.csv", 1.0);
  for (const char* bounds : {"0.5", "2:3", "0:2", "0.5:x", "0.5:2:3", "-1:2"}) {
    const CliRun r =
        run_fit_family(a + " " + b + " --model bingham --viscosity-nuisance " + bounds);
    EXPECT_EQ(r.code, 2) << bounds;
    EXPECT_NE(r.err.find("--viscosity-nuisance: expected LO:HI"), std::string::npos) << r.err;
  }
  fs::remove_all(dir);
}

// --motion-lead takes auto or a number of seconds within +-0.1 s; anything else exits 2 naming
// the option and what it expects, before any fit. A given lead is stored in the model
// (setup.motion_lead_s) and named in the text output.
TEST(FitFamilyCli, MotionLeadIsAutoOrSecondsAndIsStored) {
  const fs::path dir = fresh_dir("lead");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "b.csv", 1.0);
  for (const char* lead : {"fast", "0.5", "-0.2", "5ms", "nan"}) {
    const CliRun r = run_fit_family(a + " " + b + " --model bingham --motion-lead " + lead);
    EXPECT_EQ(r.code, 2) << lead;
    EXPECT_NE(r.err.find("--motion-lead"), std::string::npos) << r.err;
  }
  const CliRun j =
      run_fit_family(a + " " + b + " --model bingham --quiet --json --motion-lead 0.005");
  ASSERT_EQ(j.code, 0) << j.err;
  EXPECT_EQ(nlohmann::json::parse(j.out).at("setup").at("motion_lead_s").get<double>(), 0.005);
  const CliRun text = run_fit_family(a + " " + b + " --model bingham --quiet --motion-lead 0.005");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("motion lead 5.0 ms"), std::string::npos) << text.out;
  fs::remove_all(dir);
}

// --hold NAME=VALUE: a Bingham family with its viscous force and transition held at the truth
// (100, 800, 2000, 5000, 0.005, 0 simulated) fits the other terms to it (reference: the truth,
// 1 %) and reports the held ones as held with no standard error; a hold without '=', a name the
// model does not have, a value outside its bounds or the same parameter twice exit 2 naming it.
TEST(FitFamilyCli, HoldsAParameterAtAValue) {
  const fs::path dir = fresh_dir("hold");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "b.csv", 1.0);
  const std::string c = write_recording_at(dir, "c.csv", 0.5);
  const std::string family = a + " " + b + " " + c + " --model bingham ";
  const CliRun r = run_fit_family(family + "--hold viscous=2000 --hold transition=0.005 --json");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["params"]["viscous"].get<double>(), 2000.0);
  EXPECT_EQ(j["params"]["transition"].get<double>(), 0.005);
  EXPECT_NEAR(j["params"]["yield"].get<double>(), 100.0, 1.0);
  EXPECT_NEAR(j["params"]["yield_per_field"].get<double>(), 800.0, 8.0);
  EXPECT_NEAR(j["params"]["viscous_per_field"].get<double>(), 5000.0, 50.0);
  const CliRun text = run_fit_family(family + "--hold viscous=2000 --quiet");
  ASSERT_EQ(text.code, 0) << text.err;
  const auto line = text.out.find("  viscous ");
  ASSERT_NE(line, std::string::npos) << text.out;
  EXPECT_NE(text.out.substr(line, text.out.find('\n', line) - line).find("(held)"),
            std::string::npos)
      << text.out;

  const std::pair<const char*, const char*> bad[] = {
      {"--hold viscous", "--hold: expected NAME=VALUE"},
      {"--hold viscous=fast", "--hold: expected NAME=VALUE"},
      {"--hold =3", "--hold: expected NAME=VALUE"},
      {"--hold inertance=20", "held parameter 'inertance': the bingham model has no such"},
      {"--hold transition=-1", "held parameter 'transition' = -1: expected a value within"},
      {"--hold viscous=1 --hold viscous=2", "parameter 'viscous' is held twice"}};
  for (const auto& [option, message] : bad) {
    const CliRun e = run_fit_family(family + option + " --quiet");
    EXPECT_EQ(e.code, 2) << option;
    EXPECT_NE(e.err.find(message), std::string::npos) << option << ": " << e.err;
  }
  fs::remove_all(dir);
}

// --cross-validate: three noise-free recordings of one Bingham truth (0, 0.5, 1 A; the field
// terms are linear in the current), so each held out is predicted by the other two exactly up to
// the fit's tolerance (reference: the truth, FIT >= 99 %); with two recordings at 0 A and one at
// 1 A, leaving the 1 A one out leaves one field level: exit 2 naming that recording, before any
// fit.
TEST(FitFamilyCli, CrossValidationPredictsEachHeldOutRecording) {
  const fs::path dir = fresh_dir("cv");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "b.csv", 0.5);
  const std::string c = write_recording_at(dir, "c.csv", 1.0);
  const CliRun r =
      run_fit_family(a + " " + b + " " + c + " --model bingham --cross-validate --json --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const nlohmann::json j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j.at("held_out").size(), 3u);
  for (std::size_t k = 0; k < 3; ++k) {
    EXPECT_EQ(j["held_out"][k]["file"], j["train"][k]["file"]);
    EXPECT_GE(j["held_out"][k]["fit_percent"].get<double>(), 99.0) << j["held_out"][k];
  }
  // d: a second test at a's current (another stroke, so not a duplicate of a).
  const std::string d = write_recording_at(dir, "d.csv", 0.0, RigKind::damper, true, 0.03);
  const CliRun broken =
      run_fit_family(a + " " + d + " " + c + " --model bingham --cross-validate --quiet");
  EXPECT_EQ(broken.code, 2);
  EXPECT_NE(broken.err.find("without " + c), std::string::npos) << broken.err;
  EXPECT_NE(broken.err.find("two or more field levels"), std::string::npos) << broken.err;
  fs::remove_all(dir);
}

// Progress on stderr (a family fit takes 10-60 s on real tests): the fit's iterations against
// their bound (2 starts x 60), then the simulation of every recording, whose last step is always
// printed; --quiet prints nothing; stdout carries only the result.
TEST(FitFamilyCli, ReportsProgressOnStderrUnlessQuiet) {
  const fs::path dir = fresh_dir("progress");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "b.csv", 1.0);
  const CliRun r = run_fit_family(a + " " + b + " --model bingham --json");
  ASSERT_EQ(r.code, 0) << r.err;
  // The first line is the first iteration to report (1, or 2 when the other start's thread
  // counted first).
  EXPECT_EQ(r.err.find("fit-family: fitting bingham, "), 0u) << r.err;
  EXPECT_NE(r.err.find(" of at most 120, "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("fit-family: simulating every recording with the fitted bingham, 2 of 2, "),
            std::string::npos)
      << r.err;
  EXPECT_TRUE(nlohmann::json::accept(r.out)) << r.out;
  const CliRun quiet = run_fit_family(a + " " + b + " --model bingham --json --quiet");
  ASSERT_EQ(quiet.code, 0) << quiet.err;
  EXPECT_EQ(quiet.err, "");
  fs::remove_all(dir);
}

// A family at 0 and 0.5 A predicting 1 A: the prediction lies above the fitted levels, and the
// JSON (beyond_training, with the fitted model's operating_range), the text and the report say
// so in the same words; the training recordings, inside the levels, say nothing.
TEST(FitFamilyCli, APredictionAboveTheFittedLevelsIsNamedEverywhere) {
  const fs::path dir = fresh_dir("beyond");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "b.csv", 0.5);
  const std::string c = write_recording_at(dir, "c.csv", 1.0);
  const std::string args = a + " " + b + " --model bingham --predict " + c;
  const CliRun r = run_fit_family(args + " --json --report " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["operating_range"]["field"]["low"].get<double>(), 0.0);
  EXPECT_EQ(j["operating_range"]["field"]["high"].get<double>(), 0.5);
  EXPECT_TRUE(j["train"][0]["beyond_training"].empty());
  ASSERT_EQ(j["prediction"][0]["beyond_training"].size(), 1u);
  const std::string text = j["prediction"][0]["beyond_training"][0]["text"].get<std::string>();
  EXPECT_EQ(text,
            "field: current up to 1 A, above the trained 0 ... 0.5 A (the model's field "
            "dependence is extrapolated)");
  const CliRun plain = run_fit_family(args);
  ASSERT_EQ(plain.code, 0) << plain.err;
  EXPECT_NE(plain.out.find("  beyond the training recordings' drive: " + c + ": " + text),
            std::string::npos)
      << plain.out;
  std::ifstream in(dir / "out" / "report.html");
  const std::string html((std::istreambuf_iterator<char>(in)), {});
  EXPECT_NE(
      html.find("<p>Beyond the training recordings' drive: " + rheomag::html_escape(text) + "</p>"),
      std::string::npos);
  fs::remove_all(dir);
}

// A Bingham family at 0 and 1 A predicts 0.5 A exactly (noise-free, same structure): FIT > 99 %
// on every recording; the JSON has standard errors; the report has a loop per recording and
// renders in headless Chromium (screenshot not blank).
TEST(FitFamilyCli, ReportRendersInHeadlessChromium) {
  const fs::path dir = fresh_dir("report");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "b.csv", 1.0);
  const std::string c = write_recording_at(dir, "c.csv", 0.5);
  const CliRun r = run_fit_family(a + " " + b + " --model bingham --predict " + c +
                                  " --json --report " + (dir / "out").string());
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["standard_errors"].contains("yield_per_field"));
  EXPECT_GT(j["prediction"][0]["fit_percent"].get<double>(), 99.0);
  // Two whole cycles of a symmetric force: the output's mean is zero, so the model is compared
  // without its own mean (docs/damper-model.md), and each recording says so.
  EXPECT_TRUE(j["train"][0]["mean_removed"].get<bool>());
  EXPECT_TRUE(j["prediction"][0]["mean_removed"].get<bool>());
  // A prediction carries its band from the parameters' disagreement between the two recordings.
  EXPECT_GE(j["prediction"][0]["band_percent"].get<double>(), 0.0);
  EXPECT_GE(j["prediction"][0]["band_rms"].get<double>(), 0.0);
  EXPECT_TRUE(j["train"][0]["band_percent"].is_null());
  // The printed model reads back (identify/fit_model_json.hpp) and predicts c.csv as printed.
  const FitModel back = parse_fit_model_json(r.out, "stdout");
  // Two recordings: every free parameter has a between-recordings (clustered) error, read back.
  for (std::size_t k = 0; k < back.greybox->params.size(); ++k)
    if (!back.greybox->params[k].fixed && j["parameters"][k]["standard_error"].is_number()) {
      ASSERT_TRUE(back.greybox->params[k].standard_error_between_recordings.has_value())
          << back.greybox->params[k].name;
      EXPECT_EQ(*back.greybox->params[k].standard_error_between_recordings,
                j["parameters"][k]["standard_error_between_recordings"].get<double>());
    }
  // The text output has the same columns of errors as the JSON: classical and between recordings.
  const CliRun text = run_fit_family(a + " " + b + " --model bingham");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("+- between recordings"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("(mean removed: compared without the model's mean)"), std::string::npos);
  const Recording rc = read_recording(c);
  const std::vector<double> y = simulate_fit_model(rc, back);
  EXPECT_NEAR(compute_metrics(rc.column("force"), y).fit_percent,
              j["prediction"][0]["fit_percent"].get<double>(), 1e-9);
  // The same model file run by `rheomag simulate` on c.csv's drive writes that output.
  std::ofstream(dir / "model.json") << r.out;
  const CliRun sim =
      rheomag::cli_test::run_rheomag("simulate " + (dir / "model.json").string() + " --input " + c +
                                     " --out " + (dir / "sim.csv").string());
  ASSERT_EQ(sim.code, 0) << sim.err;
  const Recording simulated = read_recording((dir / "sim.csv").string());
  ASSERT_EQ(simulated.column("force").size(), y.size());
  for (std::size_t i = 0; i < y.size(); ++i) EXPECT_EQ(simulated.column("force")[i], y[i]) << i;
  const CliRun no_input = rheomag::cli_test::run_rheomag(
      "simulate " + (dir / "model.json").string() + " --signal velocity=constant:value=0.1 --out " +
      (dir / "sim2.csv").string());
  EXPECT_EQ(no_input.code, 2);
  EXPECT_NE(no_input.err.find("a fitted model runs on a recording's drive columns"),
            std::string::npos)
      << no_input.err;
  std::ifstream in(dir / "out" / "report.html");
  const std::string html((std::istreambuf_iterator<char>(in)), {});
  std::size_t svgs = 0;
  for (std::size_t at = html.find("<svg"); at != std::string::npos; at = html.find("<svg", at + 1))
    ++svgs;
  EXPECT_EQ(svgs, 6u);  // force-displacement and force-velocity for 3 recordings
  EXPECT_NE(html.find("standard error"), std::string::npos);
  EXPECT_NE(html.find("between recordings"), std::string::npos);
  EXPECT_NE(html.find("band % (1&sigma;, parameters between recordings)"), std::string::npos);
  EXPECT_NE(html.find("reversals: % of the residual energy in % of the samples"),
            std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);  // self-contained
  if (run("command -v chromium > /dev/null 2>&1") != 0) GTEST_SKIP() << "chromium not installed";
  const fs::path png = dir / "report.png";
  EXPECT_EQ(
      run("timeout 120 chromium --headless --no-sandbox --disable-gpu "
          "--disable-background-networking --disable-component-update --no-first-run "
          "--hide-scrollbars --window-size=1000,1600 --screenshot=" +
          png.string() + " file://" + (dir / "out" / "report.html").string() + " > /dev/null 2>&1"),
      0);
  ASSERT_TRUE(fs::exists(png));
  EXPECT_GT(fs::file_size(png), 30000u);  // a blank page compresses to a few kB
  if (const char* keep = std::getenv("RHEOMAG_KEEP_SCREENSHOT"))
    fs::copy_file(png, keep, fs::copy_options::overwrite_existing);
  fs::remove_all(dir);
}

// Issue 34: fit-family fitted on every 4th sample without saying what that means; the text now
// states the rule (identify::decimation_text) and gives every parameter's unit and remark.
TEST(FitFamilyCli, TextStatesTheSampleRule) {
  const fs::path dir = fresh_dir("rule");
  const std::string a = write_recording_at(dir, "a.csv", 0.0);
  const std::string b = write_recording_at(dir, "b.csv", 1.0);
  const CliRun r = run_fit_family(a + " " + b + " --model bingham --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_NE(r.out.find("samples: the fit uses every 4th sample of each training recording "
                       "(--decimation 4, default 4"),
            std::string::npos)
      << r.out;
  EXPECT_NE(r.out.find("N/A"), std::string::npos) << r.out;  // yield_per_field [N/A]
  fs::remove_all(dir);
}
