// Bad input to the diagnosis (issue 5): recordings the reader rejects, a sidecar lacking what the
// baseline needs (the message names the key), too short or too flat recordings (exit 2), and the
// CLI's outputs (JSON on stdout, diagnosis.json / report.html / traces.csv, a headless-Chromium
// screenshot of the report).

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/error.hpp"
#include "diagnose/diagnose_report.hpp"
#include "diagnose/diagnose_run.hpp"
#include "lumped/recording_io.hpp"
#include "test_diagnose_fixture.hpp"

namespace {

namespace fs = std::filesystem;
using rheomag::InputError;
using rheomag::diagnose::diagnose;

rheomag::test::VirtualRecording clean_bypass(double duration = 1.0) {
  return rheomag::test::make_recording(
      rheomag::test::bypass_rig(),
      rheomag::test::drive(duration, 200.0,
                           {"displacement=sine:amplitude=0.025,frequency=1",
                            "current=steps:levels=0/1/0.5,period=0.3"}),
      3e4);
}

/// The InputError message of diagnose(rec), or "" if it did not throw one.
std::string diagnose_error(const rheomag::lumped::Recording& rec) {
  try {
    (void)diagnose(rec);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

fs::path temp_dir(const std::string& name) {
  const auto dir = fs::temp_directory_path() / ("rheomag_diagnose_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

int run(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string slurp(const fs::path& p) {
  std::ifstream f(p);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

TEST(DiagnoseInput, MissingPistonAreaIsNamed) {
  auto v = clean_bypass();
  v.noisy.meta.rig.piston_area.reset();
  EXPECT_NE(diagnose_error(v.noisy).find("piston_area"), std::string::npos);
}

TEST(DiagnoseInput, MissingValveMapIsNamed) {
  auto v = clean_bypass();
  v.noisy.meta.valve.yield_pressure.clear();
  EXPECT_NE(diagnose_error(v.noisy).find("yield_pressure"), std::string::npos);
  v = clean_bypass();
  v.noisy.meta.valve.viscous_resistance.reset();
  EXPECT_NE(diagnose_error(v.noisy).find("viscous_resistance"), std::string::npos);
}

TEST(DiagnoseInput, VoltageDrivenCoilNeedsResistance) {
  auto v = clean_bypass();
  v.noisy.columns["voltage"] = v.noisy.column("current");
  v.noisy.meta.drive = {"velocity", "voltage"};
  v.noisy.meta.coil.resistance.reset();
  EXPECT_NE(diagnose_error(v.noisy).find("[coil] resistance"), std::string::npos);
}

TEST(DiagnoseInput, TooShortAndTooFlat) {
  auto v = clean_bypass(0.2);  // 40 samples
  EXPECT_NE(diagnose_error(v.noisy).find("too short"), std::string::npos);
  v = clean_bypass();
  for (double& p : v.noisy.columns["pressure"]) p = 1e5;
  EXPECT_NE(diagnose_error(v.noisy).find("flat"), std::string::npos);
}

TEST(DiagnoseCli, RejectsWhatTheReaderRejectsWithExit2) {
  const auto dir = temp_dir("bad");
  const auto v = clean_bypass();
  rheomag::lumped::write_recording(v.noisy, (dir / "rec.csv").string());
  // NaN in the output column.
  const auto text = slurp(dir / "rec.csv");
  const auto header_end =
      text.find('\n', text.rfind("\n#") == std::string::npos ? 0 : text.rfind("\n#") + 1);
  const auto header = text.substr(0, header_end);
  std::string nan_row = "99";
  for (char c : header.substr(header.rfind('\n') == std::string::npos ? 0 : header.rfind('\n')))
    if (c == ',') nan_row += ",nan";
  std::ofstream(dir / "nan.csv") << text << nan_row << "\n";
  fs::copy_file(dir / "rec.toml", dir / "nan.toml");
  const std::string bin = RHEOMAG_BINARY;
  EXPECT_EQ(run(bin + " diagnose " + (dir / "nan.csv").string() + " > /dev/null 2>&1"), 2);
  // Missing sidecar.
  fs::copy_file(dir / "rec.csv", dir / "lonely.csv");
  EXPECT_EQ(run(bin + " diagnose " + (dir / "lonely.csv").string() + " > /dev/null 2>&1"), 2);
  // Missing file.
  EXPECT_EQ(run(bin + " diagnose " + (dir / "none.csv").string() + " > /dev/null 2>&1"), 2);
  // An excerpt outside the recording, reversed, or malformed.
  for (const char* samples : {"0:999999999", "50:10", "x:y"})
    EXPECT_EQ(run(bin + " diagnose " + (dir / "rec.csv").string() + " --samples " + samples +
                  " > /dev/null 2>&1"),
              2)
        << samples;
}

TEST(DiagnoseCli, WritesJsonReportAndTraces) {
  const auto dir = temp_dir("out");
  const auto v = clean_bypass();
  rheomag::lumped::write_recording(v.noisy, (dir / "rec.csv").string());
  const std::string bin = RHEOMAG_BINARY;
  ASSERT_EQ(run(bin + " diagnose " + (dir / "rec.csv").string() + " --json --out " +
                (dir / "out").string() + " > " + (dir / "stdout.json").string() + " 2> " +
                (dir / "stderr.txt").string()),
            0);
  // Progress: each candidate of a selection step counted with the time left in the step.
  const std::string progress = slurp(dir / "stderr.txt");
  EXPECT_NE(progress.find("diagnose: step 1 "), std::string::npos) << progress;
  EXPECT_NE(progress.find(" of at most "), std::string::npos) << progress;
  EXPECT_NE(progress.find(" left: "), std::string::npos) << progress;
  // The output set: its three files, no staging folder left.
  int files = 0;
  for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(dir / "out"))
    ++files;
  EXPECT_EQ(files, 3);
  const auto j = nlohmann::json::parse(slurp(dir / "stdout.json"));
  for (const char* key : {"baseline", "mismatch", "missing_physics", "final"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_TRUE(j["missing_physics"].empty());
  EXPECT_EQ(nlohmann::json::parse(slurp(dir / "out" / "diagnosis.json"))["final"], j["final"]);
  const auto html = slurp(dir / "out" / "report.html");
  EXPECT_NE(html.find("<svg"), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);  // self-contained
  EXPECT_NE(slurp(dir / "out" / "traces.csv").find("t,measured,baseline,final"), std::string::npos);
}

// The report renders in headless Chromium: the screenshot exists and is not blank.
TEST(DiagnoseCli, ReportScreenshotInHeadlessChromium) {
  if (run("command -v chromium > /dev/null 2>&1") != 0) GTEST_SKIP() << "chromium not installed";
  const auto dir = temp_dir("shot");
  auto truth = rheomag::test::bypass_rig();
  rheomag::lumped::ChamberBlock chamber;
  chamber.air_volume = 3e-7;
  truth.compressibility = chamber;
  const auto v = rheomag::test::make_recording(
      truth,
      rheomag::test::drive(1.5, 200.0,
                           {"displacement=sine:amplitude=0.025,frequency=1",
                            "current=steps:levels=0/1/0.5,period=0.3"}),
      3e4);
  const auto d = diagnose(v.noisy);
  rheomag::diagnose::write_diagnosis_outputs(d, dir.string());
  const auto png = dir / "report.png";
  const int rc =
      run("timeout 120 chromium --headless --no-sandbox --disable-gpu "
          "--disable-background-networking --disable-component-update --no-first-run "
          "--hide-scrollbars --window-size=1000,1600 --screenshot=" +
          png.string() + " file://" + (dir / "report.html").string() + " > /dev/null 2>&1");
  EXPECT_EQ(rc, 0);
  ASSERT_TRUE(fs::exists(png));
  // A blank page compresses to a few kB; three plots with text do not.
  EXPECT_GT(fs::file_size(png), 30000u);
  if (const char* keep = std::getenv("RHEOMAG_KEEP_SCREENSHOT"))
    fs::copy_file(png, keep, fs::copy_options::overwrite_existing);
}

}  // namespace
