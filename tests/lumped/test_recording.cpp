// Recording reader/writer: round trip, the real data in shared/data, and every bad input the
// format names (missing sidecar, missing columns, empty cells, non-numbers, NaN, non-increasing t).

#include <gtest/gtest.h>

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/error.hpp"
#include "lumped/recording_excerpt.hpp"
#include "lumped/recording_io.hpp"

using namespace rheomag::lumped;
namespace fs = std::filesystem;

namespace {

const char* kSidecar =
    "[recording]\ndescription = \"test\"\ndrive = [\"velocity\", \"current\"]\n"
    "output = \"pressure\"\n[rig]\nkind = \"bypass_cylinder\"\npiston_area = 4.524e-4\n"
    "[valve]\nyield_current = [0.0, 1.0]\nyield_pressure = [0.0, 5.8e6]\n"
    "viscous_resistance = 1.5e10\n[coil]\nresistance = 8.9\n";

class RecordingFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() /
           ("rheomag_rec_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
            "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string write(const std::string& csv, const char* sidecar = kSidecar) {
    std::string path = (dir_ / "rec.csv").string();
    std::ofstream(path) << csv;
    if (sidecar) std::ofstream((dir_ / "rec.toml").string()) << sidecar;
    return path;
  }
  /// The InputError message of reading `csv`, or "" if none was thrown.
  std::string error_of(const std::string& csv, const char* sidecar = kSidecar) {
    std::string path = write(csv, sidecar);
    try {
      read_recording(path);
    } catch (const rheomag::InputError& e) {
      return e.what();
    }
    return "";
  }
  fs::path dir_;
};

}  // namespace

TEST_F(RecordingFiles, ReadsAnyColumnOrderCommentsAndIgnoresUnknown) {
  std::string path = write(
      "# a comment\n# another\npressure,t,extra,velocity,current\n1e5,0,9,0.01,0.5\n"
      "2e5,0.001,9,0.02,0.5\n3e5,0.002,9,0.03,0.5\n");
  Recording rec = read_recording(path);
  // The reader returns its warnings (the CLI prints them); it prints nothing itself.
  ASSERT_EQ(rec.warnings.size(), 1u);
  EXPECT_NE(rec.warnings[0].find("ignoring unknown column 'extra'"), std::string::npos);
  ASSERT_EQ(rec.t.size(), 3u);
  EXPECT_DOUBLE_EQ(rec.t[2], 0.002);
  EXPECT_DOUBLE_EQ(rec.column("pressure")[1], 2e5);
  EXPECT_DOUBLE_EQ(rec.column("velocity")[2], 0.03);
  EXPECT_EQ(rec.columns.count("extra"), 0u);
  EXPECT_EQ(rec.meta.output, "pressure");
  EXPECT_EQ(rec.meta.rig.kind, rheomag::lumped::RigKind::bypass_cylinder);
  EXPECT_DOUBLE_EQ(*rec.meta.rig.piston_area, 4.524e-4);
  EXPECT_DOUBLE_EQ(rec.meta.valve.yield_pressure[1], 5.8e6);
  EXPECT_DOUBLE_EQ(*rec.meta.coil.resistance, 8.9);
  EXPECT_THROW(rec.column("force"), rheomag::InputError);
}

TEST_F(RecordingFiles, WriteThenReadIsIdentical) {
  Recording rec;
  rec.t = {0.0, 0.1, 0.25};
  rec.columns["velocity"] = {0.01, -0.02, 1.0 / 3.0};
  rec.columns["current"] = {0.0, 0.5, 1.0};
  rec.columns["pressure"] = {1.234567890123e5, -2e6, 3.3e-7};
  rec.meta.description = "round trip";
  rec.meta.drive = {"velocity", "current"};
  rec.meta.output = "pressure";
  rec.meta.rig.kind = rheomag::lumped::RigKind::bypass_cylinder;
  rec.meta.rig.piston_area = 4.524e-4;
  rec.meta.valve.yield_current = {0.0, 1.0};
  rec.meta.valve.yield_pressure = {0.0, 5.8e6};
  rec.meta.valve.viscous_resistance = 1.5e10;
  rec.meta.coil.inductance = 0.12;
  std::string path = (dir_ / "out.csv").string();
  write_recording(rec, path);
  Recording back = read_recording(path);
  // Shortest round-trip formatting: values must come back bit-identical.
  EXPECT_EQ(back.t, rec.t);
  EXPECT_EQ(back.columns, rec.columns);
  EXPECT_EQ(back.meta.drive, rec.meta.drive);
  EXPECT_EQ(back.meta.description, "round trip");
  EXPECT_DOUBLE_EQ(*back.meta.valve.viscous_resistance, 1.5e10);
  EXPECT_DOUBLE_EQ(*back.meta.coil.inductance, 0.12);
  EXPECT_FALSE(fs::exists(path + ".tmp." + std::to_string(::getpid())));
}

TEST_F(RecordingFiles, MissingSidecar) {
  std::string msg = error_of("t,velocity,current,pressure\n0,0,0,0\n1,1,1,1\n", nullptr);
  EXPECT_NE(msg.find("rec.toml"), std::string::npos) << msg;
  EXPECT_NE(msg.find("sidecar"), std::string::npos) << msg;
}

TEST_F(RecordingFiles, MissingDriveOrOutputColumn) {
  std::string msg = error_of("t,velocity,pressure\n0,0,0\n1,1,1\n");
  EXPECT_NE(msg.find("drive column 'current'"), std::string::npos) << msg;
  msg = error_of("t,velocity,current\n0,0,0\n1,1,1\n");
  EXPECT_NE(msg.find("output column 'pressure'"), std::string::npos) << msg;
}

TEST_F(RecordingFiles, BadCellsNameLineAndColumn) {
  const std::string head = "# c\nt,velocity,current,pressure\n0,0,0,0\n";
  std::string msg = error_of(head + "1,,0,0\n");
  EXPECT_NE(msg.find(":4:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("empty cell in column 'velocity'"), std::string::npos) << msg;
  msg = error_of(head + "1,0,abc,0\n");
  EXPECT_NE(msg.find(":4:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("'current'"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not a number"), std::string::npos) << msg;
  msg = error_of(head + "1,0,0,nan\n");
  EXPECT_NE(msg.find("NaN or infinite"), std::string::npos) << msg;
  msg = error_of(head + "1,0,0,-inf\n");
  EXPECT_NE(msg.find("NaN or infinite"), std::string::npos) << msg;
  msg = error_of(head + "1,0,0,0\n1,0,0,0\n");
  EXPECT_NE(msg.find(":5:"), std::string::npos) << msg;
  EXPECT_NE(msg.find("not strictly increasing"), std::string::npos) << msg;
  msg = error_of(head + "1,0,0\n");
  EXPECT_NE(msg.find("expected 4 cells"), std::string::npos) << msg;
  msg = error_of("velocity,current,pressure\n0,0,0\n1,1,1\n");
  EXPECT_NE(msg.find("'t'"), std::string::npos) << msg;
  msg = error_of("t,velocity,current,pressure\n0,0,0,0\n");
  EXPECT_NE(msg.find("at least 2 samples"), std::string::npos) << msg;
}

TEST_F(RecordingFiles, BadSidecar) {
  const std::string csv = "t,velocity,current,pressure\n0,0,0,0\n1,1,1,1\n";
  std::string msg = error_of(csv, "[recording]\noutput = \"pressure\"\n");
  EXPECT_NE(msg.find("drive"), std::string::npos) << msg;
  msg =
      error_of(csv, "[recording]\ndrive=[\"velocity\"]\noutput=\"pressure\"\n[rig]\nkind=\"x\"\n");
  EXPECT_NE(msg.find("rec.toml:5: rig.kind: expected"), std::string::npos) << msg;
  msg = error_of(csv, "[recording\n");
  EXPECT_NE(msg.find("rec.toml:1"), std::string::npos) << msg;
}

// The shared real recordings parse with their stated sizes (mrdamper: 3499 samples, Ts = 5 ms).
TEST(SharedRecordings, MrdamperParses) {
  Recording rec = read_recording(std::string(RHEOMAG_SHARED_DIR) + "/data/mrdamper/mrdamper.csv");
  EXPECT_EQ(rec.t.size(), 3499u);
  EXPECT_NEAR(rec.t[1] - rec.t[0], 0.005, 1e-12);
  EXPECT_EQ(rec.meta.output, "force");
  EXPECT_EQ(rec.meta.rig.kind, rheomag::lumped::RigKind::damper);
}

TEST(SharedRecordings, ExcerptKeepsColumnsTimesAndSidecar) {
  // Reference: the full recording's own samples 100..299.
  const Recording rec =
      read_recording(std::string(RHEOMAG_SHARED_DIR) + "/data/mrdamper/mrdamper.csv");
  const Recording part = excerpt(rec, SampleRange{100, 300});
  ASSERT_EQ(part.t.size(), 200u);
  EXPECT_EQ(part.t.front(), rec.t[100]);
  EXPECT_EQ(part.t.back(), rec.t[299]);
  ASSERT_EQ(part.columns.size(), rec.columns.size());
  for (const auto& [name, values] : rec.columns) {
    ASSERT_EQ(part.columns.at(name).size(), 200u) << name;
    EXPECT_EQ(part.columns.at(name)[7], values[107]) << name;
  }
  EXPECT_EQ(part.meta.output, rec.meta.output);
  EXPECT_THROW(excerpt(rec, SampleRange{3000, 4000}), rheomag::InputError);
  EXPECT_THROW(excerpt(rec, SampleRange{10, 10}), rheomag::InputError);
}
