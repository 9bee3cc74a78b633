// The one atomic writer: the target is either the old file or the complete new one, never a
// temporary left behind, and special files are refused untouched.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/output_set.hpp"

namespace fs = std::filesystem;
using rheomag::InputError;

namespace {

fs::path scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rheomag_atomic_" + name);
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

int files_in(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

}  // namespace

TEST(AtomicFile, WritesAndReplacesWithoutLeavingTemporaries) {
  const fs::path dir = scratch("replace");
  rheomag::write_file_atomically(dir / "out.csv", "first\n");
  EXPECT_EQ(read(dir / "out.csv"), "first\n");
  rheomag::write_file_atomically(dir / "out.csv", "second\n");
  EXPECT_EQ(read(dir / "out.csv"), "second\n");
  EXPECT_EQ(files_in(dir), 1);
}

TEST(AtomicFile, MissingDirectoryIsAnInputErrorNamingThePath) {
  const fs::path dir = scratch("missing");
  try {
    rheomag::write_file_atomically(dir / "no" / "out.csv", "x");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no/out.csv"), std::string::npos) << e.what();
  }
}

// `solve --vtk nodir/field.vtu`: VTK's writer only reports failure, and the message said "cannot
// write: the writer failed"; the system's reason names the missing directory.
TEST(AtomicFile, WriterIntoMissingDirectorySaysWhy) {
  const fs::path dir = scratch("missing_with");
  try {
    rheomag::write_file_atomically_with(dir / "no" / "field.vtu",
                                        [](const fs::path&) { return false; });
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              (dir / "no" / "field.vtu").string() + ": cannot write: No such file or directory");
  }
  EXPECT_FALSE(fs::exists(dir / "no"));
}

TEST(AtomicFile, RefusesDirectoriesAndDeviceNodes) {
  const fs::path dir = scratch("special");
  EXPECT_THROW(rheomag::write_file_atomically(dir, "x"), InputError);
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_THROW(rheomag::write_file_atomically("/dev/null", "x"), InputError);
  EXPECT_TRUE(fs::is_character_file("/dev/null"));
  EXPECT_THROW(rheomag::write_file_atomically("", "x"), InputError);
}

TEST(AtomicFile, FailedProducerKeepsTheOldFileAndRemovesItsTemporary) {
  const fs::path dir = scratch("producer");
  rheomag::write_file_atomically(dir / "out.vtu", "old");
  EXPECT_THROW(rheomag::write_file_atomically_with(dir / "out.vtu",
                                                   [](const fs::path& tmp) {
                                                     std::ofstream(tmp) << "half";
                                                     return false;
                                                   }),
               InputError);
  EXPECT_EQ(read(dir / "out.vtu"), "old");
  EXPECT_EQ(files_in(dir), 1);
  // A producer that writes nothing has failed too.
  EXPECT_THROW(
      rheomag::write_file_atomically_with(dir / "out.vtu", [](const fs::path&) { return true; }),
      InputError);
  EXPECT_EQ(read(dir / "out.vtu"), "old");
  rheomag::write_file_atomically_with(dir / "out.vtu", [](const fs::path& tmp) {
    std::ofstream(tmp) << "new";
    return true;
  });
  EXPECT_EQ(read(dir / "out.vtu"), "new");
  EXPECT_EQ(files_in(dir), 1);
}

// A set of output files (a recording and its sidecar, a diagnosis folder, a VTK series) replaces
// its previous version as a whole: until commit the old set is untouched, a failure before the
// commit leaves it whole with no staging folder behind, and the commit removes only the old set's
// leftovers (issue #36: on a full disk `simulate --out` left the new CSV beside the old sidecar).

TEST(OutputSet, CommitReplacesTheSetAndRemovesOnlyItsLeftovers) {
  const fs::path dir = scratch("set_commit");
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
  EXPECT_EQ(files_in(dir), 2);  // no staging folder left
}

TEST(OutputSet, FailureBeforeCommitLeavesTheOldSetWhole) {
  const fs::path dir = scratch("set_failure");
  rheomag::write_file_atomically(dir / "rec.csv", "old csv");
  rheomag::write_file_atomically(dir / "rec.toml", "old sidecar");
  try {
    rheomag::OutputSet pair(dir, "--out");
    rheomag::write_file_atomically(pair.staged("rec.csv"), "new csv");
    // A writer's error names the destination, not the staging folder.
    try {
      pair.write("rec.toml", [](const fs::path& to) {
        throw rheomag::InputError(to.string() + ": cannot write: No space left on device");
      });
    } catch (const rheomag::InputError& e) {
      EXPECT_EQ(std::string(e.what()),
                (dir / "rec.toml").string() + ": cannot write: No space left on device");
    }
    throw std::runtime_error("the sidecar could not be written");  // e.g. the disk is full
  } catch (const std::runtime_error&) {
  }
  EXPECT_EQ(read(dir / "rec.csv"), "old csv");
  EXPECT_EQ(read(dir / "rec.toml"), "old sidecar");
  EXPECT_EQ(files_in(dir), 2);
}

TEST(OutputSet, DestinationThatIsAFolderIsRefusedBeforeAnythingMoves) {
  const fs::path dir = scratch("set_folder");
  rheomag::write_file_atomically(dir / "a.csv", "old a");
  fs::create_directories(dir / "b.toml");
  rheomag::OutputSet set(dir, "--out");
  rheomag::write_file_atomically(set.staged("a.csv"), "new a");
  rheomag::write_file_atomically(set.staged("b.toml"), "new b");
  EXPECT_THROW(set.commit(), rheomag::InputError);
  EXPECT_EQ(read(dir / "a.csv"), "old a");
}

TEST(OutputSet, CreatesAMissingFolderAndNamesTheOptionWhenItCannot) {
  const fs::path dir = scratch("set_create");
  {
    rheomag::OutputSet set(dir / "new" / "deeper", "--out");
    rheomag::write_file_atomically(set.staged("x.json"), "{}\n");
    set.commit();
  }
  EXPECT_EQ(read(dir / "new" / "deeper" / "x.json"), "{}\n");
  // A file's own folder (simulate --out REC.csv) is not made up: a missing one is refused.
  EXPECT_THROW(rheomag::OutputSet(dir / "missing", "--out", rheomag::OutputSet::Folder::must_exist),
               rheomag::InputError);
  EXPECT_FALSE(fs::exists(dir / "missing"));
  rheomag::write_file_atomically(dir / "plain", "a file, not a folder");
  try {
    rheomag::OutputSet set(dir / "plain", "--out");
    FAIL() << "a file taken for the folder was accepted";
  } catch (const rheomag::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--out"), std::string::npos) << e.what();
  }
}
