// The one atomic writer: the target is either the old file or the complete new one, never a
// temporary left behind, and special files are refused untouched.

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/atomic_file.hpp"
#include "core/error.hpp"

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
