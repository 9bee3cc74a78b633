// The one input reader: special files (devices, FIFOs, directories) are refused by name before
// anything is read, a FIFO without a writer does not block, and the size is bounded.

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "core/input_file.hpp"

namespace fs = std::filesystem;
using rheomag::InputError;
using rheomag::read_input_file;
using ::testing::HasSubstr;

namespace {

fs::path input_scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rheomag_input_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string refusal(const fs::path& path, std::uintmax_t limit = rheomag::kMaxInputFileBytes) {
  try {
    read_input_file(path, limit);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(InputFile, RegularFileIsReadWhole) {
  const fs::path dir = input_scratch("regular");
  std::ofstream(dir / "a.toml", std::ios::binary) << "x = 1\n";
  EXPECT_EQ(read_input_file(dir / "a.toml"), "x = 1\n");
  // A symbolic link to a regular file is read (a case kept elsewhere).
  fs::create_symlink(dir / "a.toml", dir / "link.toml");
  EXPECT_EQ(read_input_file(dir / "link.toml"), "x = 1\n");
  fs::remove_all(dir);
}

TEST(InputFile, DevicesAreRefusedByNameBeforeReading) {
  // /dev/zero would be read to exhaustion (7.8 GB, then bad_alloc) if it were opened for reading.
  const auto start = std::chrono::steady_clock::now();
  const std::string zero = refusal("/dev/zero");
  EXPECT_THAT(zero, HasSubstr("/dev/zero: input file is a character device"));
  EXPECT_THAT(zero, HasSubstr("expected a regular file"));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  EXPECT_THAT(refusal("/dev/null"), HasSubstr("character device"));
}

TEST(InputFile, FifoWithoutWriterIsRefusedWithoutBlocking) {
  const fs::path dir = input_scratch("fifo");
  ASSERT_EQ(::mkfifo((dir / "pipe.csv").c_str(), 0600), 0);
  // No writer: an open for reading without O_NONBLOCK would wait forever.
  EXPECT_THAT(refusal(dir / "pipe.csv"), HasSubstr("pipe.csv: input file is a FIFO (named pipe)"));
  fs::remove_all(dir);
}

TEST(InputFile, DirectoryAndMissingFileAreNamed) {
  const fs::path dir = input_scratch("dir");
  EXPECT_THAT(refusal(dir), HasSubstr("is a directory"));
  EXPECT_THAT(refusal(dir / "missing.toml"),
              HasSubstr("missing.toml: cannot open file: No such file or directory"));
  fs::remove_all(dir);
}

TEST(InputFile, SizeAboveTheLimitIsRefusedWithBothSizes) {
  const fs::path dir = input_scratch("size");
  std::ofstream(dir / "big.csv", std::ios::binary) << std::string(3000, 'x');
  EXPECT_EQ(read_input_file(dir / "big.csv", 3000).size(), 3000u);  // at the limit: read
  const std::string message = refusal(dir / "big.csv", 2999);
  EXPECT_THAT(message, HasSubstr("big.csv: the file holds 3e-06 GB, more than the 3e-06 GB"));
  fs::remove_all(dir);
}
