// rheomag simulate: CLI round trip (simulate -> read back with the recording reader), agreement
// with the library call, every bundled rig spec runs, and bad specs exit with code 2.

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <unistd.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "coupling/simulation_spec.hpp"
#include "lumped/recording_io.hpp"
#include "lumped/signals.hpp"

using namespace rheomag::lumped;
using namespace rheomag::coupling;
namespace fs = std::filesystem;

namespace {

int run(const std::string& args) {
  const std::string cmd = std::string(RHEOMAG_BINARY) + " " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WEXITSTATUS(status);
}

std::string rigs() {
  return std::string(RHEOMAG_SOURCE_DIR) + "/cases/rigs/";
}

fs::path temp_dir(const std::string& name) {
  fs::path d =
      fs::temp_directory_path() / ("rheomag_sim_" + name + "_" + std::to_string(::getpid()));
  fs::create_directories(d);
  return d;
}

}  // namespace

// Simulated recording read back: same samples, drive columns, output; equal (to the shortest
// round-trip formatting, i.e. exactly) to the library's own simulation with the same seed.
TEST(Simulate, CliRoundTrip) {
  fs::path dir = temp_dir("rt");
  const std::string out = (dir / "sim.csv").string();
  const std::string sig =
      " --signal displacement=sine:amplitude=0.025,frequency=0.75"
      " --signal current=steps:levels=0/0.5/1,period=1 --duration 3 --rate 500";
  ASSERT_EQ(run("simulate " + rigs() + "bypass_cylinder.toml" + sig + " --out " + out), 0);
  Recording rec = read_recording(out);
  EXPECT_EQ(rec.t.size(), 1500u);
  EXPECT_EQ(rec.meta.output, "pressure");
  EXPECT_EQ(rec.meta.drive, (std::vector<std::string>{"velocity", "current"}));
  EXPECT_EQ(rec.meta.rig.kind, rheomag::lumped::RigKind::bypass_cylinder);
  EXPECT_NEAR(*rec.meta.rig.piston_area, 4.524e-4, 1e-7);  // paper 001: 452.4 mm^2

  Recording drive;
  drive.t = uniform_times(3, 500);
  add_signal(drive, "displacement=sine:amplitude=0.025,frequency=0.75");
  add_signal(drive, "current=steps:levels=0/0.5/1,period=1");
  Recording lib = simulate_spec(read_simulation_spec(rigs() + "bypass_cylinder.toml"), drive);
  EXPECT_EQ(rec.column("pressure"), lib.column("pressure"));
  // The peak pressure at 1 A is near the table's 5.8 MPa + viscous drop (0.6 MPa at 53 ml/s).
  double peak = 0.0;
  for (std::size_t k = 1000; k < 1500; ++k)
    peak = std::max(peak, std::abs(rec.column("pressure")[k]));
  EXPECT_GT(peak, 5.8e6);
  EXPECT_LT(peak, 7.5e6);

  // Reading it back as --input reproduces it (noise re-drawn with the same seed).
  const std::string out2 = (dir / "sim2.csv").string();
  ASSERT_EQ(run("simulate " + rigs() + "bypass_cylinder.toml --input " + out + " --out " + out2),
            0);
  Recording rec2 = read_recording(out2);
  ASSERT_EQ(rec2.t.size(), rec.t.size());
  for (std::size_t k = 0; k < rec.t.size(); k += 97)
    EXPECT_NEAR(rec2.column("pressure")[k], rec.column("pressure")[k], 1e-6 * 7e6);
  fs::remove_all(dir);
}

// Every bundled spec in cases/rigs runs on a short generated drive and writes a readable recording.
TEST(Simulate, BundledSpecsRun) {
  fs::path dir = temp_dir("all");
  const std::string drive =
      " --signal displacement=sine:amplitude=0.01,frequency=1 --signal "
      "current=steps:levels=0/1,period=0.5"
      " --signal voltage=square:low=0,high=5,period=0.5 --signal "
      "command=steps:levels=0/2,period=0.5"
      " --duration 1 --rate 1000";
  for (const auto& entry : fs::directory_iterator(rigs())) {
    if (entry.path().extension() != ".toml") continue;
    const std::string out = (dir / (entry.path().stem().string() + ".csv")).string();
    ASSERT_EQ(run("simulate " + entry.path().string() + drive + " --out " + out), 0)
        << entry.path();
    Recording rec = read_recording(out);
    EXPECT_EQ(rec.t.size(), 1000u) << entry.path();
  }
  fs::remove_all(dir);
}

TEST(Simulate, BadSpecsExitWith2) {
  fs::path dir = temp_dir("bad");
  auto spec = [&](const std::string& text) {
    std::string p = (dir / "spec.toml").string();
    std::ofstream(p) << text;
    return p;
  };
  const std::string drive =
      " --signal velocity=constant:value=0.01 --signal current=constant:value=1"
      " --duration 0.1 --rate 100 --out " +
      (dir / "o.csv").string();
  EXPECT_EQ(run("simulate " + spec("[rig]\nkind = \"pump\"\n") + drive), 2);
  EXPECT_EQ(run("simulate " +
                spec("[rig]\nkind = \"bypass_cylinder\"\n[valve]\n"
                     "yield_current=[0,1]\nyield_pressure=[0,1e6]\n"
                     "[effects.air]\nx=1\n") +
                drive),
            2);
  EXPECT_EQ(run("simulate " + spec("[model]\nkind = \"bouc-wen\"\n") + drive), 2);
  EXPECT_EQ(run("simulate " + rigs() + "bypass_cylinder.toml --signal velocity=wobble:x=1" +
                " --out " + (dir / "o.csv").string()),
            2);
  EXPECT_EQ(run("simulate " + rigs() +
                "bypass_cylinder.toml --signal velocity=constant:value=1"
                " --duration 0.1 --out " +
                (dir / "o.csv").string()),
            2);  // no current drive
  EXPECT_EQ(run("simulate /nonexistent.toml" + drive), 2);
  try {
    read_simulation_spec(
        spec("[rig]\nkind = \"bypass_cylinder\"\n[valve]\nyield_current=[0,1]\n"
             "yield_pressure=[0,1e6]\nviscous_resistance = -1\n"));
    FAIL() << "negative viscous resistance accepted";
  } catch (const rheomag::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("viscous_resistance"), std::string::npos) << e.what();
  }
  // A fluid heating with a negative resistance, or on a rig without a valve, names the key.
  for (const std::string& text :
       {std::string("[rig]\nkind = \"bypass_cylinder\"\n[valve]\nyield_current=[0,1]\n"
                    "yield_pressure=[0,1e6]\n[effects.fluid_heating]\nthermal_resistance = -1\n"),
        std::string("[rig]\nkind = \"coil_bench\"\n[effects.fluid_heating]\n")}) {
    try {
      read_simulation_spec(spec(text));
      FAIL() << "accepted: " << text;
    } catch (const rheomag::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("effects.fluid_heating"), std::string::npos) << e.what();
    }
  }
  // The valve table's knee (lumped/slit_law.hpp) is a fraction in [0, 1]; a case's chain map is
  // already its gap's exact law, so a knee beside a case is refused too.
  const std::string table =
      "[rig]\nkind = \"bypass_cylinder\"\n[valve]\nyield_current=[0,1]\nyield_pressure=[0,1e6]\n";
  EXPECT_DOUBLE_EQ(
      read_simulation_spec(spec(table + "slit_fraction = 0.5\n")).rig->valve.slit_fraction, 0.5);
  for (const std::string& text :
       {table + "slit_fraction = 1.5\n",
        std::string("[rig]\nkind = \"bypass_cylinder\"\n[valve]\ncase = \"") + rigs() +
            "../annular_valve.toml\"\nslit_fraction = 0.5\n"}) {
    try {
      read_simulation_spec(spec(text));
      FAIL() << "accepted: " << text;
    } catch (const rheomag::InputError& e) {
      EXPECT_NE(std::string(e.what()).find("[valve] slit_fraction"), std::string::npos) << e.what();
    }
  }
  fs::remove_all(dir);
}
