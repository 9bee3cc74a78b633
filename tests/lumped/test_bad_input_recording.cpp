// Bad input of recordings (issue #18's probe): every physical value of a sidecar has a declared
// domain and a value outside it is refused at read time with file, line and key; CSVs with a
// UTF-8 byte-order mark are read; a CSV with another separator is refused naming it; a constant
// output is refused naming file and column (narx on it: tests/identify/test_ident_nonlinear.cpp).

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#include "core/error.hpp"
#include "core/finite_output.hpp"
#include "lumped/recording_io.hpp"

using ::testing::HasSubstr;
using namespace rheomag::lumped;
namespace fs = std::filesystem;

namespace {

/// A valid damper sidecar; `rig` replaces the [rig] table's lines 6-8 (piston_area on line 7).
std::string sidecar(const std::string& rig_lines,
                    const std::string& valve_lines = "viscous_resistance = 1.3e8\n") {
  return "[recording]\n"             // 1
         "drive = [\"velocity\"]\n"  // 2
         "output = \"force\"\n"      // 3
         "\n"                        // 4
         "[rig]\n"                   // 5
         "kind = \"damper\"\n" +     // 6
         rig_lines +                 // 7, 8, ...
         "\n[valve]\n"
         "yield_current = [0.0, 1.0]\n"
         "yield_pressure = [0.0, 6.0e4]\n" +
         valve_lines;
}

/// The InputError message of parsing `text` as a sidecar ("" if it parses).
std::string sidecar_error(const std::string& text) {
  try {
    parse_sidecar(text, "rec.toml");
  } catch (const rheomag::InputError& e) {
    return e.what();
  }
  return "";
}

std::string csv_error(const std::string& text) {
  try {
    parse_csv_samples(text, "rec.csv");
  } catch (const rheomag::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(BadInputSidecar, ValidSidecarReads) {
  const RecordingMeta meta =
      parse_sidecar(sidecar("piston_area = 1.0e-3\nchamber_volume = 2.0e-5\n"), "rec.toml");
  EXPECT_DOUBLE_EQ(*meta.rig.piston_area, 1.0e-3);
  EXPECT_DOUBLE_EQ(*meta.rig.chamber_volume, 2.0e-5);
  EXPECT_DOUBLE_EQ(*meta.valve.viscous_resistance, 1.3e8);
}

// Zero piston area sent diagnose to 16.8 GB and std::bad_alloc; a negative one was used.
TEST(BadInputSidecar, PistonAreaMustBePositive) {
  EXPECT_EQ(sidecar_error(sidecar("piston_area = 0.0\n")),
            "rec.toml:7: rig.piston_area: expected a number in (0, 10] (m^2), got 0");
  EXPECT_EQ(sidecar_error(sidecar("piston_area = -1.0e-3\n")),
            "rec.toml:7: rig.piston_area: expected a number in (0, 10] (m^2), got -0.001");
}

// 1e300 m^2 printed "FIT -inf %" with exit 0: an area is a physical size, at most 10 m^2.
TEST(BadInputSidecar, PistonAreaMustBePhysical) {
  EXPECT_EQ(sidecar_error(sidecar("piston_area = 1.0e300\n")),
            "rec.toml:7: rig.piston_area: expected a number in (0, 10] (m^2), got 1e+300");
}

// A negative chamber volume turned the diagnosis into "none".
TEST(BadInputSidecar, ChamberVolumeMustBePositive) {
  EXPECT_EQ(sidecar_error(sidecar("piston_area = 1.0e-3\nchamber_volume = -2.0e-5\n")),
            "rec.toml:8: rig.chamber_volume: expected a number in (0, 10] (m^3), got -2e-05");
}

TEST(BadInputSidecar, ViscousResistanceMustBePositive) {
  EXPECT_EQ(sidecar_error(sidecar("piston_area = 1.0e-3\n", "viscous_resistance = -1.3e8\n")),
            "rec.toml:12: valve.viscous_resistance: expected a positive number (Pa s/m^3), got "
            "-130000000");
}

TEST(BadInputSidecar, YieldPressureMustBeNonNegative) {
  const std::string text =
      "[recording]\ndrive = [\"velocity\"]\noutput = \"force\"\n[valve]\n"
      "yield_current = [0.0, 1.0]\nyield_pressure = [0.0, -6.0e4]\n";
  EXPECT_EQ(sidecar_error(text),
            "rec.toml:6: valve.yield_pressure: item 2: expected a number >= 0 (Pa), got -60000");
}

TEST(BadInputSidecar, RodAreaBelowPistonArea) {
  EXPECT_EQ(sidecar_error(sidecar("piston_area = 1.0e-3\nrod_area = 2.0e-3\n")),
            "rec.toml:8: rig.rod_area: expected less than piston_area = 0.001 m^2, got 0.002");
}

TEST(BadInputSidecar, OrientationIsOneOrMinusOne) {
  EXPECT_EQ(sidecar_error(sidecar("piston_area = 1.0e-3\norientation = 0.5\n")),
            "rec.toml:8: rig.orientation: expected a whole number in [-1, 1], got 0.5");
  EXPECT_EQ(sidecar_error(sidecar("piston_area = 1.0e-3\norientation = 0\n")),
            "rec.toml:8: rig.orientation: expected 1 or -1, got 0");
}

TEST(BadInputSidecar, CoilResistanceMustBePositive) {
  EXPECT_EQ(sidecar_error(sidecar("piston_area = 1.0e-3\n") + "[coil]\nresistance = 0\n"),
            "rec.toml:14: coil.resistance: expected a positive number (ohm), got 0");
}

// A misspelt key silently dropped the value; unknown keys far from any known one stay allowed.
TEST(BadInputSidecar, MisspeltKeyRefused) {
  EXPECT_EQ(sidecar_error(sidecar("piston_aera = 1.0e-3\n")),
            "rec.toml:7: unknown key 'rig.piston_aera'; did you mean 'rig.piston_area'?");
  EXPECT_EQ(sidecar_error(sidecar("piston_area = 1.0e-3\nstroke_length = 0.05\n")), "");
}

TEST(BadInputSidecar, TextWhereANumberBelongs) {
  EXPECT_EQ(sidecar_error(sidecar("piston_area = \"1e-3\"\n")),
            "rec.toml:7: rig.piston_area: expected a number");
}

// A CSV saved with a UTF-8 byte-order mark was refused with "no 't' column".
// A sidecar listing its output among the drive columns (or a drive twice) was accepted: an ARX
// fit then used the output as its own input and went unstable (|pole| 2.3e13), bingham ignored it.
TEST(BadInputSidecar, DriveColumnsAreDistinctInputs) {
  EXPECT_EQ(sidecar_error("[recording]\ndrive = [\"velocity\", \"force\"]\noutput = \"force\"\n"),
            "rec.toml:2: recording.drive: column 'force' is also the output; expected the measured "
            "inputs that drive the model (e.g. velocity, current), not the signal it explains");
  EXPECT_EQ(
      sidecar_error("[recording]\ndrive = [\"velocity\", \"velocity\"]\noutput = \"force\"\n"),
      "rec.toml:2: recording.drive: column 'velocity' is listed twice; expected each drive column "
      "once");
}

TEST(BadInputCsv, ByteOrderMarkAccepted) {
  const Recording rec = parse_csv_samples("\xEF\xBB\xBFt,force\n0,1\n0.1,2\n", "rec.csv");
  ASSERT_EQ(rec.t.size(), 2u);
  EXPECT_DOUBLE_EQ(rec.column("force")[1], 2.0);
}

TEST(BadInputCsv, OtherSeparatorNamed) {
  EXPECT_EQ(csv_error("t;force\n0;1\n0.1;2\n"),
            "rec.csv:1: the header 't;force' has no comma; expected comma-separated columns (',' "
            "between cells, '.' as the decimal point), this file seems to use ';'");
  EXPECT_EQ(csv_error("t\tforce\n0\t1\n"),
            "rec.csv:1: the header 't\tforce' has no comma; expected comma-separated columns (',' "
            "between cells, '.' as the decimal point), this file seems to use tabs");
}

TEST(BadInputCsv, NonFiniteCellRefused) {
  EXPECT_EQ(csv_error("t,force\n0,1\n0.1,nan\n"),
            "rec.csv:3: 'nan' in column 'force' is NaN or infinite");
}

// Quoted cells (spreadsheet and DAQ exports: "t","force") read as their contents, a comma inside
// quotes does not split, and "" inside quotes is one quote.
TEST(BadInputCsv, QuotedCellsAreRead) {
  const Recording rec = parse_csv_samples(
      "\"t\", \"force\",\"note, free\"\n\"0\",1.5,\"a \"\"b\"\"\"\n0.1,\"2\",c\n", "rec.csv");
  ASSERT_EQ(rec.t.size(), 2u);
  EXPECT_EQ(rec.t[1], 0.1);
  EXPECT_EQ(rec.column("force")[0], 1.5);
  EXPECT_EQ(rec.column("force")[1], 2.0);
  EXPECT_EQ(csv_error("\"t\",\"force\"\n0,1\n0.1,\"x\"\n"),
            "rec.csv:3: 'x' in column 'force' is not a number");
}

// Headers with units: "force [N]" / "t (s)" in the column's SI unit read as the column; another
// unit is refused naming the SI one (the format is SI: no silent scaling); a column in another case
// or named "time" is not guessed, but the message names the column it resembles.
TEST(BadInputCsv, HeaderUnitsAndNamesResembled) {
  const Recording rec = parse_csv_samples(
      "t (s),velocity [m/s],flow [m3/s],force [N]\n0,1,2,3\n0.1,4,5,6\n", "rec.csv");
  EXPECT_EQ(rec.column("force")[1], 6.0);
  EXPECT_EQ(rec.column("flow")[0], 2.0);
  EXPECT_EQ(rec.t[1], 0.1);
  EXPECT_EQ(csv_error("t,displacement [mm]\n0,1\n0.1,2\n"),
            "rec.csv:1: column 'displacement [mm]': the recording format's 'displacement' is in "
            "m; convert the column to m (the format is SI throughout)");
  EXPECT_EQ(csv_error("t,force,force [N]\n0,1,1\n0.1,2,2\n"),
            "rec.csv:1: column 'force [N]' appears twice (as 'force')");
  EXPECT_EQ(csv_error("time,Force\n0,1\n0.1,2\n"),
            "rec.csv:1: no 't' column (time in s is required); the header has 'time': name it 't'");
  const Recording hinted = parse_csv_samples("t,Force\n0,1\n0.1,2\n", "rec.csv");
  ASSERT_EQ(hinted.warnings.size(), 1u);
  EXPECT_EQ(hinted.warnings[0],
            "rec.csv: ignoring unknown column 'Force'; did you mean 'force'? (columns are named "
            "in lower case, in SI units: force in N)");
}

// Spreadsheet exports end every row with a comma: the unnamed last column is ignored with a
// warning, its cells unread.
TEST(BadInputCsv, UnnamedColumnIgnored) {
  const Recording rec = parse_csv_samples("t,force,\n0,1,\n0.1,2,x\n", "rec.csv");
  EXPECT_EQ(rec.column("force")[1], 2.0);
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_EQ(rec.warnings[0], "rec.csv: ignoring unnamed column 3 (an empty header cell)");
}

// A sidecar naming a column the CSV lacks: the message lists the CSV's columns and, for a name
// that is not a column of the format, the one it resembles.
TEST(BadInputSidecar, MissingColumnListsTheCsvColumns) {
  const fs::path dir =
      fs::temp_directory_path() / ("rheomag_missing_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  std::ofstream(dir / "r.csv") << "t,velocity,force\n0,1,2\n0.1,2,3\n";
  std::ofstream(dir / "r.toml") << "[recording]\ndrive = [\"velocity\"]\noutput = \"Force\"\n";
  const std::string csv = (dir / "r.csv").string(), toml = (dir / "r.toml").string();
  EXPECT_THAT([&] { read_recording(csv); },
              ::testing::ThrowsMessage<rheomag::InputError>(
                  toml + ": [recording] output column 'Force' is not in " + csv +
                  " (its columns: t, force, velocity); did you mean 'force'? (columns are named in "
                  "lower case, in SI units: force in N)"));
  std::ofstream(dir / "r.toml") << "[recording]\ndrive = [\"flow\"]\noutput = \"force\"\n";
  EXPECT_THAT([&] { read_recording(csv); },
              ::testing::ThrowsMessage<rheomag::InputError>(
                  toml + ": [recording] drive column 'flow' is not in " + csv +
                  " (its columns: t, force, velocity)"));
  fs::remove_all(dir);
}

// A finite but absurd cell (1e200 N: its square overflows, so every FIT from it would be NaN) is
// refused at its line; 1e15 itself and an unknown column's value are not checked against it.
TEST(BadInputCsv, AbsurdMagnitudeRefused) {
  EXPECT_EQ(csv_error("t,force\n0,1\n0.1,1e200\n"),
            "rec.csv:3: '1e200' in column 'force' is beyond any measured magnitude (|value| > "
            "1e15 in SI units); expected a measured value");
  EXPECT_EQ(csv_error("t,force\n0,1\n0.1,-2e15\n"),
            "rec.csv:3: '-2e15' in column 'force' is beyond any measured magnitude (|value| > "
            "1e15 in SI units); expected a measured value");
  EXPECT_NO_THROW(parse_csv_samples("t,force,note\n0,1e15,1e200\n0.1,2,3\n", "rec.csv"));
}

// Constant-output errors named no file or column.
TEST(BadInputRecording, ConstantOutputNamed) {
  Recording rec = parse_csv_samples("t,velocity,force\n0,1,5\n0.1,2,5\n0.2,3,5\n", "rec.csv");
  EXPECT_THAT([&] { rec.require_varying("force"); },
              ::testing::ThrowsMessage<rheomag::InputError>(
                  "rec.csv: column 'force' is constant (5) on samples 0:3; there is nothing to "
                  "identify"));
  EXPECT_NO_THROW(rec.require_varying("velocity"));
}

// An output that varies only by rounding (5 +- 1e-13, a constant passed through a float export)
// was fitted with exit 0 and printed FIT -103 %; it is as constant as diagnose's "flat" output.
TEST(BadInputRecording, OutputConstantToRoundingNamed) {
  Recording rec = parse_csv_samples(
      "t,velocity,force\n0,1,5\n0.1,2,5.0000000000001\n0.2,3,5\n0.3,1,5.000001\n", "rec.csv");
  EXPECT_THAT([&] { rec.require_varying("force", 0, 3); },
              ::testing::ThrowsMessage<rheomag::InputError>(
                  "rec.csv: column 'force' is constant (to 9 significant digits: 5, spread "
                  "1e-13) on samples 0:3; there is nothing to identify"));
  EXPECT_NO_THROW(rec.require_varying("force"));  // 2e-7 relative: a measured change
}

// `simulate model.json` with a parameter of 1e308 produced an infinite force; the writer said
// "p.csv: non-finite value at sample 1" with exit 2, as if the input were wrong and without the
// column. It is a non-finite result (exit 3) naming the column and time; nothing is written.
TEST(BadInputRecording, NonFiniteSimulatedColumnIsANonFiniteResult) {
  Recording rec = parse_csv_samples("t,velocity,force\n0,1,5\n0.1,2,6\n", "in.csv");
  rec.meta.drive = {"velocity"};
  rec.meta.output = "force";
  rec.columns["force"][1] = std::numeric_limits<double>::infinity();
  const std::string path =
      (std::filesystem::temp_directory_path() / "rheomag_nonfinite_written.csv").string();
  std::filesystem::remove(path);
  EXPECT_THAT([&] { write_recording(rec, path); },
              ::testing::ThrowsMessage<rheomag::NonFiniteOutputError>(
                  path + ": column 'force' at sample 1 (t = 0.1 s) is not a finite number; the "
                         "recording was not written"));
  EXPECT_FALSE(std::filesystem::exists(path));
}

// A recording exported on Windows as REC.CSV + REC.TOML was refused on Linux: "REC.toml: sidecar
// not found", though the sidecar has the recording's stem.
TEST(BadInputRecording, SidecarWithCapitalExtensionIsFound) {
  const auto dir = std::filesystem::temp_directory_path() / "rheomag_capital_sidecar";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "REC.CSV") << "t,velocity,force\n0,1,5\n0.1,2,6\n0.2,3,4\n";
  std::ofstream(dir / "REC.TOML") << "[recording]\ndrive = [\"velocity\"]\noutput = \"force\"\n";
  const Recording rec = read_recording((dir / "REC.CSV").string());
  EXPECT_EQ(rec.meta.output, "force");
  EXPECT_EQ(rec.meta.sidecar_path, (dir / "REC.TOML").string());
  std::filesystem::remove_all(dir);
}
