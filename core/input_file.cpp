// open(O_NONBLOCK) + fstat: the type is checked on the file actually opened (no race with a
// rename), and opening a FIFO without a writer does not block.

#include "core/input_file.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <new>
#include <system_error>

#include "core/error.hpp"

namespace rheomag {
namespace {

/// "a directory", "a FIFO (named pipe)", ... for the type bits of `mode`.
std::string special_file_kind(mode_t mode) {
  if (S_ISDIR(mode)) return "a directory";
  if (S_ISFIFO(mode)) return "a FIFO (named pipe)";
  if (S_ISCHR(mode)) return "a character device";
  if (S_ISBLK(mode)) return "a block device";
  if (S_ISSOCK(mode)) return "a socket";
  return "not a regular file";
}

[[noreturn]] void refuse_special_file(const std::filesystem::path& path, std::string_view what,
                                      mode_t mode) {
  throw InputError(path.string() + ": " + std::string(what) + " is " + special_file_kind(mode) +
                   "; expected a regular file (special files are not read)");
}

std::string size_text(double bytes) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g GB", bytes / 1e9);
  return text;
}

}  // namespace

void require_regular_input_file(const std::filesystem::path& path, std::string_view what) {
  if (path.empty()) throw InputError(std::string(what) + ": expected a file name, got \"\"");
  struct stat status {};
  if (::stat(path.c_str(), &status) != 0) {
    const int error = errno;
    throw InputError(path.string() +
                     ": cannot open file: " + std::generic_category().message(error));
  }
  if (!S_ISREG(status.st_mode)) refuse_special_file(path, what, status.st_mode);
}

std::string read_input_file(const std::filesystem::path& path, std::uintmax_t max_bytes) {
  require_regular_input_file(path, "input file");
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    const int error = errno;
    throw InputError(path.string() +
                     ": cannot open file: " + std::generic_category().message(error));
  }
  struct FdCloser {
    int fd;
    ~FdCloser() { ::close(fd); }
  } closer{fd};
  struct stat status {};
  if (::fstat(fd, &status) != 0) throw InputError(path.string() + ": cannot read file");
  if (!S_ISREG(status.st_mode)) refuse_special_file(path, "input file", status.st_mode);
  const auto size = static_cast<std::uintmax_t>(status.st_size);
  if (size > max_bytes) {
    throw InputError(path.string() + ": the file holds " + size_text(static_cast<double>(size)) +
                     ", more than the " + size_text(static_cast<double>(max_bytes)) +
                     " an input file may hold");
  }
  std::string text;
  try {
    text.resize(static_cast<std::size_t>(size));
  } catch (const std::bad_alloc&) {
    throw InputError(path.string() + ": not enough memory to read its " +
                     size_text(static_cast<double>(size)));
  }
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::read(fd, text.data() + done, text.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int error = errno;
      throw InputError(path.string() +
                       ": cannot read file: " + std::generic_category().message(error));
    }
    if (n == 0) break;  // the file shrank while it was read
    done += static_cast<std::size_t>(n);
  }
  text.resize(done);
  return text;
}

}  // namespace rheomag
