// Issue #18's probe of the command line, end to end through the rheomag binary: each class of bad
// input ends in exit 2 with a message naming file, line and key (or the option), never a crash,
// a silent wrong result or a device node replaced; valid input that was refused is read.

#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/cli_run.hpp"

namespace fs = std::filesystem;

namespace {

using rheomag::cli_test::CliRun;

/// Runs `rheomag ARGS` in `dir`.
CliRun run_in(const fs::path& dir, const std::string& args) {
  return rheomag::cli_test::run_rheomag(args, dir);
}

class BadInputCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir = fs::temp_directory_path() /
          ("rheomag_bad_input_" +
           std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(dir);
    fs::create_directories(dir);
  }
  void TearDown() override { fs::remove_all(dir); }

  /// A 400-sample damper recording (velocity sine, force `force(k)`) with `sidecar` beside it.
  void recording(const std::string& stem, const std::string& sidecar, double (*force)(int)) const {
    std::ofstream csv(dir / (stem + ".csv"));
    csv << "t,velocity,force\n";
    for (int k = 0; k < 400; ++k)
      csv << k * 0.005 << ',' << 0.05 * std::sin(0.1 * k) << ',' << force(k) << '\n';
    std::ofstream(dir / (stem + ".toml")) << sidecar;
  }
  void write(const std::string& name, const std::string& text) const {
    std::ofstream(dir / name) << text;
  }
  /// rec.csv (a damper recording with a piston area) and model.json, the Bingham model that
  /// `fit --json` writes of it: the baseline of `diagnose --baseline` (defined below).
  void fitted_model() const;
  /// The bundled annular valve case with line `from` replaced by `to`.
  void annular_case(const std::string& name, const std::string& from, const std::string& to) {
    std::ifstream in(std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml");
    std::ostringstream text;
    text << in.rdbuf();
    std::string s = text.str();
    const std::size_t at = s.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    s.replace(at, from.size(), to);
    write(name, s);
  }
  fs::path dir;
};

const char* kDamperSidecar =
    "[recording]\ndrive = [\"velocity\"]\noutput = \"force\"\n"                // lines 1-3
    "[rig]\nkind = \"damper\"\npiston_area = AREA\nchamber_volume = 2.0e-5\n"  // 4-7
    "[valve]\nyield_current = [0.0, 1.0]\nyield_pressure = [0.0, 6.0e4]\n"
    "viscous_resistance = 1.3e8\n";

std::string damper_sidecar(const std::string& area) {
  std::string s = kDamperSidecar;
  s.replace(s.find("AREA"), 4, area);
  return s;
}

double sine_force(int k) {
  return 400.0 * std::tanh(std::sin(0.1 * k) / 0.3);
}
double constant_force(int) {
  return 5.0;
}

void BadInputCli::fitted_model() const {
  recording("rec", damper_sidecar("1.0e-3"), sine_force);
  const CliRun fit = run_in(dir, "fit rec.csv --model bingham --json");
  ASSERT_EQ(fit.code, 0) << fit.err;
  write("model.json", fit.out);
}

}  // namespace

// narx of a constant output died with SIGSEGV (exit 139).
TEST_F(BadInputCli, ConstantOutputNarxIsExit2NamingFileAndColumn) {
  recording("flat", damper_sidecar("1.0e-3"), constant_force);
  for (const char* model : {"narx:2,2,1", "arx:2,2,1", "bingham"}) {
    const CliRun r = run_in(dir, std::string("fit flat.csv --model ") + model);
    EXPECT_EQ(r.code, 2) << model << ": " << r.err;
    EXPECT_NE(r.err.find("flat.csv: column 'force' is constant (5) on samples 0:400"),
              std::string::npos)
        << model << ": " << r.err;
  }
}

// A zero piston area sent diagnose to 16.8 GB and std::bad_alloc (exit 1).
TEST_F(BadInputCli, ZeroPistonAreaIsExit2AtReadTime) {
  recording("rec", damper_sidecar("0.0"), sine_force);
  const CliRun r = run_in(dir, "diagnose rec.csv --quiet");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("rec.toml:6: rig.piston_area: expected a number in (0, 10] (m^2), got 0"),
            std::string::npos)
      << r.err;
}

// 1e300 m^2 printed "FIT -inf %" with exit 0 and Ceres' glog lines on stderr.
TEST_F(BadInputCli, AbsurdPistonAreaIsExit2WithoutThirdPartyLogging) {
  recording("rec", damper_sidecar("1.0e300"), sine_force);
  const CliRun r = run_in(dir, "diagnose rec.csv --quiet");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err,
            "rheomag: error: rec.toml:6: rig.piston_area: expected a number in (0, 10] (m^2), got "
            "1e+300\n");
  EXPECT_EQ(r.out.find("nan"), std::string::npos);
}

// A CSV written with a UTF-8 byte-order mark was refused with "no 't' column".
TEST_F(BadInputCli, ByteOrderMarkCsvIsRead) {
  recording("plain", damper_sidecar("1.0e-3"), sine_force);
  std::ifstream in(dir / "plain.csv");
  std::ostringstream text;
  text << "\xEF\xBB\xBF" << in.rdbuf();
  write("bom.csv", text.str());
  write("bom.toml", damper_sidecar("1.0e-3"));
  const CliRun r = run_in(dir, "fit bom.csv --model arx:2,2,1");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err.find("unknown column"), std::string::npos) << r.err;
}

// `--vtk ""` wrote nothing and said nothing.
TEST_F(BadInputCli, EmptyVtkPathIsExit2) {
  const std::string c = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";
  const CliRun r = run_in(dir, "mesh '" + c + "' --vtk ''");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("--vtk"), std::string::npos) << r.err;
}

// An empty option value (a script's unset variable: `--out "$DIR"`) read as the option's absence:
// `diagnose --out ''` wrote nothing, `fit --plot ''` drew nothing, `valve --wire ''` used the
// case's wire, each with exit 0. Refused when the command line is parsed, naming the option.
TEST_F(BadInputCli, EmptyOptionValuesAreExit2) {
  const std::string c = "'" + std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml'";
  for (const std::string& args : std::vector<std::string>{
           "diagnose rec.csv --out ''", "diagnose rec.csv --meta ''",
           "diagnose rec.csv --samples ''", "diagnose rec.csv --baseline ''",
           "fit rec.csv --model arx:2,2,1 --plot ''", "fit rec.csv --model arx:2,2,1 --train ''",
           "fit rec.csv --model arx:2,2,1 --validate ''",
           "fit-family rec.csv --model bingham --report ''",
           "fit-family rec.csv --model bingham --predict ''", "optimise " + c + " --out ''",
           "simulate spec.toml --input '' --out x.csv", "valve " + c + " --wire ''",
           "transient " + c + " --current 1 --duration 1 --vtk-series ''",
           "transient " + c + " --current 1 --duration 1 --scheme ''",
           "solve " + c + " --3d --mesher ''"}) {
    const CliRun r = run_in(dir, args);
    EXPECT_EQ(r.code, 2) << args << "\n" << r.err;
    EXPECT_NE(r.err.find("got \"\""), std::string::npos) << args << "\n" << r.err;
    EXPECT_EQ(r.out, "") << args;
  }
}

// `--vtk` onto a device node replaced the node by a regular file; a FIFO stands in for the node
// here (no root needed, nothing of the system at stake if this regresses).
TEST_F(BadInputCli, VtkOntoNonRegularFileIsRefusedAndTheFileKept) {
  const fs::path fifo = dir / "field.vtu";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const std::string c = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";
  const CliRun r = run_in(dir, "mesh '" + c + "' --vtk field.vtu");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_TRUE(fs::is_fifo(fifo));
  for (const auto& entry : fs::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

// In-domain but extreme values whose result overflows: `flow` printed "dp = inf Pa" with exit 0.
// The stdout guard holds the line back and ends the command with exit 3 naming it and the
// command line.
TEST_F(BadInputCli, InfiniteFlowResultIsExit3AndNotPrinted) {
  const std::string args =
      "flow --kind annular --gap 1e-3 --length 1e300 --radius 0.01 --tau-y 1e5 --viscosity 1 "
      "--flow 1e-5";
  const CliRun text = run_in(dir, args);
  EXPECT_EQ(text.code, 3) << text.err;
  EXPECT_EQ(text.out, "annular gap, exact model, wall velocity 0 m/s\n");
  EXPECT_EQ(text.err,
            "rheomag: result is not a finite number: stdout line 2 holds a non-finite number "
            "('inf' in \"  pressure drop        dp            = inf Pa (inf bar)\"); it and the "
            "rest of the output were held back; produced by: rheomag " +
                args + "\n");
  const CliRun json = run_in(dir, args + " --json");
  EXPECT_EQ(json.code, 3) << json.err;
  EXPECT_EQ(json.out, "");
  // The JSON document is checked before it is printed: the message names the key.
  EXPECT_EQ(json.err,
            "rheomag: result is not a finite number: stdout (JSON): key 'dp' is not a finite "
            "number; the result was not written; produced by: rheomag " +
                args + " --json\n");
}

/// A force of 1e200 N: in the CSV's domain (finite), but its squares overflow.
double overflowing_force(int k) {
  return 1e200 * std::sin(0.1 * k);
}

// A force of 1e200 N made a fit whose metrics or parameters overflow: it printed "FIT -nan %"
// (text) or null (JSON, nlohmann writes NaN as null) with exit 0, then exit 3 from the output
// guard, far from the cause. Now the reader refuses the cell: exit 2 naming the file, line and
// column, for every model, and nothing from Ceres/glog on stderr. (The output guard itself: core's
// FiniteOutput tests.)
TEST_F(BadInputCli, OverflowingCellIsExit2NamingItsLine) {
  recording("big", damper_sidecar("1.0e-3"), overflowing_force);
  const std::string expected =
      "rheomag: error: big.csv:3: '9.98334e+198' in column 'force' is beyond any measured "
      "magnitude (|value| > 1e15 in SI units); expected a measured value\n";
  for (const char* model : {"bingham", "arx:2,2,1 --json"}) {
    const CliRun r = run_in(dir, std::string("fit big.csv --model ") + model);
    EXPECT_EQ(r.code, 2) << model << r.err;
    EXPECT_EQ(r.out, "") << model;
    EXPECT_EQ(r.err, expected) << model;
  }
}

// `--vtk` on a full disk exited 0 with a truncated file in place of the old one, VTK's error on
// stderr. Needs a small tmpfs (root); skipped where it cannot be mounted.
TEST_F(BadInputCli, VtkOnFullDiskIsExit2KeepsTheOldFileAndNoVtkLogging) {
  const fs::path full = dir / "full";
  fs::create_directories(full);
  if (std::system(
          ("mount -t tmpfs -o size=16k tmpfs '" + full.string() + "' 2>/dev/null").c_str()) != 0)
    GTEST_SKIP() << "cannot mount a tmpfs here";
  write("full/fill", std::string(12000, '\0'));
  write("full/field.vtu", "old");
  const std::string c = std::string(RHEOMAG_SOURCE_DIR) + "/cases/annular_valve.toml";
  const CliRun r = run_in(dir, "mesh '" + c + "' --vtk full/field.vtu");
  std::string kept;
  {
    std::ifstream in(full / "field.vtu");
    kept.assign(std::istreambuf_iterator<char>(in), {});
  }  // closed before the unmount
  std::size_t temporaries = 0;
  for (const auto& entry : fs::directory_iterator(full))
    temporaries += entry.path().filename().string().find(".tmp") != std::string::npos;
  std::system(("umount '" + full.string() + "'").c_str());
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_EQ(r.err, "rheomag: error: full/field.vtu: cannot write: the writer failed\n");
  EXPECT_EQ(kept, "old");
  EXPECT_EQ(temporaries, 0u);
}

// diagnose --baseline MODEL.json: the model written by `fit --json` is read back and used as the
// baseline (its output and parameters listed in baseline.includes); a model of another rig kind
// is exit 2 naming the model file, its key and both rig kinds.
TEST_F(BadInputCli, FittedModelBaselineIsUsedAndAnotherRigKindIsExit2) {
  fitted_model();
  const CliRun ok = run_in(dir, "diagnose rec.csv --baseline model.json --json --quiet");
  EXPECT_EQ(ok.code, 0) << ok.err;
  EXPECT_NE(ok.out.find("\"fitted_model\""), std::string::npos) << ok.out;
  EXPECT_NE(ok.out.find("\"output_scale\""), std::string::npos) << ok.out;

  std::string pump = damper_sidecar("1.0e-3");
  pump.replace(pump.find("damper"), 6, "bypass_cylinder");
  recording("other", pump, sine_force);
  const CliRun r = run_in(dir, "diagnose other.csv --baseline model.json --quiet");
  EXPECT_EQ(r.code, 2) << r.err;
  EXPECT_NE(r.err.find("model.json: key 'rig': the model was fitted on a damper rig, but the "
                       "recording (other.toml) is from a bypass_cylinder rig"),
            std::string::npos)
      << r.err;
}

// On a fitted-model baseline the candidates linear in their size carry it with the sign free
// (docs/diagnosis.md, "Signed sizes"): in the JSON at the first step (signed_params with
// signed_units; the moving mass beside the inertance, in kg), and in the text report. Here
// friction and fluid_inertia (gas_spring needs a displacement column).
TEST_F(BadInputCli, FittedModelBaselineReportsSignedSizes) {
  fitted_model();
  const CliRun js = run_in(dir, "diagnose rec.csv --baseline model.json --json --quiet");
  ASSERT_EQ(js.code, 0) << js.err;
  const auto j = nlohmann::json::parse(js.out);
  std::vector<std::string> with_sign;
  for (const auto& c : j.at("candidates")) {
    if (!c.contains("signed_params")) continue;
    with_sign.push_back(c.at("name").get<std::string>());
    EXPECT_EQ(c.at("step").get<int>(), 1);
    for (const auto& [name, value] : c.at("signed_params").items()) {
      EXPECT_TRUE(std::isfinite(value.get<double>())) << name;
      EXPECT_TRUE(c.at("signed_units").contains(name)) << name;
    }
    if (with_sign.back() == "fluid_inertia") {
      EXPECT_EQ(c.at("signed_units").at("moving_mass"), "kg");
      EXPECT_NEAR(c.at("signed_params").at("moving_mass").get<double>(),
                  c.at("signed_params").at("inertance").get<double>() * 1e-6, 1e-12);
    }
  }
  std::sort(with_sign.begin(), with_sign.end());
  EXPECT_EQ(with_sign, (std::vector<std::string>{"fluid_inertia", "friction"}));
  const CliRun text = run_in(dir, "diagnose rec.csv --baseline model.json --quiet");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("signed sizes against the baseline ("), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("\n  friction: coulomb_force = "), std::string::npos) << text.out;
}

// A recording driven beyond what the baseline model was fitted on (here twice its peak speed) is
// diagnosed, and the diagnosis says so: baseline.beyond_training names the quantity and a note
// says a mismatch there may be the model's extrapolation; on the fitted recording itself,
// nothing.
TEST_F(BadInputCli, FittedModelBaselineNamesADriveBeyondItsTraining) {
  fitted_model();
  {
    std::ofstream csv(dir / "fast.csv");
    csv << "t,velocity,force\n";
    for (int k = 0; k < 400; ++k)
      csv << k * 0.005 << ',' << 0.1 * std::sin(0.1 * k) << ',' << sine_force(k) << '\n';
  }
  write("fast.toml", damper_sidecar("1.0e-3"));
  const CliRun fast = run_in(dir, "diagnose fast.csv --baseline model.json --json --quiet");
  ASSERT_EQ(fast.code, 0) << fast.err;
  const auto j = nlohmann::json::parse(fast.out);
  const auto& beyond = j.at("baseline").at("beyond_training");
  ASSERT_EQ(beyond.size(), 1u) << beyond;
  EXPECT_EQ(beyond[0].at("quantity"), "speed");
  EXPECT_EQ(beyond[0].at("unit"), "m/s");
  EXPECT_NEAR(beyond[0].at("value").get<double>(), 0.1, 1e-3);
  EXPECT_NEAR(beyond[0].at("trained_high").get<double>(), 0.05, 1e-3);
  const std::string note =
      "the recording's drive is beyond the baseline model's training drive (speed: velocity peak "
      "0.1 m/s, above the trained peaks 0.05 m/s): a mismatch there may be the model's "
      "extrapolation, not missing physics";
  EXPECT_NE(std::find(j.at("notes").begin(), j.at("notes").end(), note), j.at("notes").end())
      << j.at("notes");
  const CliRun same = run_in(dir, "diagnose rec.csv --baseline model.json --json --quiet");
  ASSERT_EQ(same.code, 0) << same.err;
  EXPECT_TRUE(nlohmann::json::parse(same.out).at("baseline").at("beyond_training").empty());
}

// `diagnose --reference`: compared through the effects' sizes against a fitted model, so without
// --baseline it is refused (exit 2 naming both options); a reference that does not exist is
// named. With the Bingham model of rec.csv, a recording with 40 N of seal friction added
// (F_c tanh(v / 1 mm/s), a tenth of the 400 N force) diagnosed against rec.csv as reference gives
// the friction's change within 10 % (the real-recording protocol's differential tolerance), in
// the JSON and in the text.
TEST_F(BadInputCli, ReferenceRecordingIsDifferencedAgainstAFittedModel) {
  fitted_model();
  const CliRun bare = run_in(dir, "diagnose rec.csv --reference rec.csv --quiet");
  EXPECT_EQ(bare.code, 2) << bare.err;
  EXPECT_NE(bare.err.find("--reference: "), std::string::npos) << bare.err;
  EXPECT_NE(bare.err.find("--baseline MODEL.json"), std::string::npos) << bare.err;
  const CliRun missing =
      run_in(dir, "diagnose rec.csv --baseline model.json --reference gone.csv --quiet");
  EXPECT_EQ(missing.code, 2) << missing.err;
  EXPECT_NE(missing.err.find("gone.csv"), std::string::npos) << missing.err;

  recording("rubbing", damper_sidecar("1.0e-3"), [](int k) {
    return sine_force(k) + 40.0 * std::tanh(0.05 * std::sin(0.1 * k) / 1e-3);
  });
  const CliRun r =
      run_in(dir, "diagnose rubbing.csv --baseline model.json --reference rec.csv --json --quiet");
  ASSERT_EQ(r.code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j.at("reference").at("recording"), "rec.csv");
  double change = 0.0;
  for (const auto& e : j.at("reference").at("changes"))
    if (e.at("name") == "friction") change = e.at("change").get<double>();
  EXPECT_NEAR(change / 40.0, 1.0, 0.1) << j.at("reference");
  const CliRun text = run_in(dir,
                             "diagnose rubbing.csv --baseline model.json --reference rec.csv "
                             "--quiet");
  ASSERT_EQ(text.code, 0) << text.err;
  EXPECT_NE(text.out.find("change against the reference rec.csv"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("friction: coulomb_force"), std::string::npos) << text.out;
}
