// A set of output files (a recording and its sidecar, a diagnosis folder, a VTK series) replaces
// its previous version as a whole: until commit the old set is untouched, a failure before the
// commit leaves it whole with no staging folder behind, and the commit removes only the old set's
// leftovers (issue #36: on a full disk `simulate --out` left the new CSV beside the old sidecar).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_set.hpp"

namespace fs = std::filesystem;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rheomag_output_set_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string read(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

int entries_in(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST(OutputSet, CommitReplacesTheSetAndRemovesOnlyItsLeftovers) {
  const fs::path dir = scratch("commit");
  rheomag::write_file_atomically(dir / "state_00000.vtu", "old 0");
  rheomag::write_file_atomically(dir / "state_00001.vtu", "old 1");
  rheomag::write_file_atomically(dir / "notes.txt", "the user's own file");
  {
    rheomag::OutputSet set(dir, "--vtk-series");
    rheomag::write_file_atomically(set.staged("state_00000.vtu"), "new 0");
    // Staged, not yet visible.
    EXPECT_EQ(read(dir / "state_00000.vtu"), "old 0");
    set.commit([](const std::string& name) { return name.rfind("state_", 0) == 0; });
  }
  EXPECT_EQ(read(dir / "state_00000.vtu"), "new 0");
  EXPECT_FALSE(fs::exists(dir / "state_00001.vtu"));  // the longer old series' last state
  EXPECT_EQ(read(dir / "notes.txt"), "the user's own file");
  EXPECT_EQ(entries_in(dir), 2);  // no staging folder left
}

TEST(OutputSet, FailureBeforeCommitLeavesTheOldSetWhole) {
  const fs::path dir = scratch("failure");
  rheomag::write_file_atomically(dir / "rec.csv", "old csv");
  rheomag::write_file_atomically(dir / "rec.toml", "old sidecar");
  try {
    rheomag::OutputSet pair(dir, "--out");
    rheomag::write_file_atomically(pair.staged("rec.csv"), "new csv");
    throw std::runtime_error("the sidecar could not be written");  // e.g. the disk is full
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read(dir / "rec.csv"), "old csv");
  EXPECT_EQ(read(dir / "rec.toml"), "old sidecar");
  EXPECT_EQ(entries_in(dir), 2);
}

TEST(OutputSet, DestinationThatIsAFolderIsRefusedBeforeAnythingMoves) {
  const fs::path dir = scratch("folder");
  rheomag::write_file_atomically(dir / "a.csv", "old a");
  fs::create_directories(dir / "b.toml");
  rheomag::OutputSet set(dir, "--out");
  rheomag::write_file_atomically(set.staged("a.csv"), "new a");
  rheomag::write_file_atomically(set.staged("b.toml"), "new b");
  EXPECT_THROW(set.commit(), rheomag::InputError);
  EXPECT_EQ(read(dir / "a.csv"), "old a");
}

TEST(OutputSet, CreatesAMissingFolderAndNamesTheOptionWhenItCannot) {
  const fs::path dir = scratch("create");
  {
    rheomag::OutputSet set(dir / "new" / "deeper", "--out");
    rheomag::write_file_atomically(set.staged("x.json"), "{}\n");
    set.commit();
  }
  EXPECT_EQ(read(dir / "new" / "deeper" / "x.json"), "{}\n");
  rheomag::write_file_atomically(dir / "plain", "a file, not a folder");
  try {
    rheomag::OutputSet set(dir / "plain", "--out");
    FAIL() << "a file taken for the folder was accepted";
  } catch (const rheomag::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--out"), std::string::npos) << e.what();
  }
}
