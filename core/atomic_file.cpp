// Temporary file in the target's directory (so rename is atomic), fsync before rename.

#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "core/error.hpp"
#include "core/finite_output.hpp"
#include "core/interrupt.hpp"

namespace rheomag {
namespace {

std::string reason(int error) {
  return std::generic_category().message(error);
}

std::filesystem::path temporary_beside(const std::filesystem::path& path) {
  std::filesystem::path temporary = path;
  temporary += ".tmp-" + std::to_string(static_cast<long>(::getpid()));
  return temporary;
}

bool write_all(int fd, std::string_view data) {
  while (!data.empty()) {
    const ssize_t n = ::write(fd, data.data(), data.size());
    if (n < 0) {
      if (errno == EINTR) continue;
      return false;
    }
    data.remove_prefix(static_cast<std::size_t>(n));
  }
  return true;
}

// fsync of an existing file (what an external writer produced); errno set on failure.
bool sync_file(const std::filesystem::path& path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool ok = ::fsync(fd) == 0;
  const int saved = errno;
  ::close(fd);
  errno = saved;
  return ok;
}

// Renames `temporary` onto `path`; removes the temporary and throws on failure.
void move_into_place(const std::filesystem::path& temporary, const std::filesystem::path& path) {
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const int saved = errno;
    std::remove(temporary.c_str());
    throw InputError(path.string() + ": cannot write: " + reason(saved));
  }
}

}  // namespace

void check_output_path(const std::filesystem::path& path, std::string_view what) {
  if (path.empty()) throw InputError(std::string(what) + ": expected a file name, got \"\"");
  std::error_code ec;
  const auto status = std::filesystem::symlink_status(path, ec);
  if (ec || status.type() == std::filesystem::file_type::not_found) return;
  if (status.type() == std::filesystem::file_type::regular) return;
  if (status.type() == std::filesystem::file_type::symlink) {
    const auto target = std::filesystem::status(path, ec);
    if (!ec && (target.type() == std::filesystem::file_type::regular ||
                target.type() == std::filesystem::file_type::not_found))
      return;
  }
  throw InputError(path.string() + ": " + std::string(what) +
                   " must be a regular file (this is a directory, device or other special file; "
                   "it is left untouched)");
}

void write_file_atomically(const std::filesystem::path& path, std::string_view content) {
  check_output_path(path, "output");
  require_finite_text(content, path.string());
  const std::filesystem::path temporary = temporary_beside(path);
  const InterruptCleanupFile removed_if_interrupted(temporary);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw InputError(path.string() + ": cannot write: " + reason(errno));
  bool ok = write_all(fd, content) && ::fsync(fd) == 0;
  int saved = errno;
  if (::close(fd) != 0 && ok) {
    ok = false;
    saved = errno;
  }
  if (!ok) {
    std::remove(temporary.c_str());
    throw InputError(path.string() + ": cannot write: " + reason(saved));
  }
  move_into_place(temporary, path);
}

void write_file_atomically_with(const std::filesystem::path& path,
                                const std::function<bool(const std::filesystem::path&)>& produce) {
  check_output_path(path, "output");
  const std::filesystem::path temporary = temporary_beside(path);
  const InterruptCleanupFile removed_if_interrupted(temporary);
  // A writer that takes a file name (VTK) says only that it failed: create the temporary first
  // so that a missing or read-only directory is reported with the system's reason.
  const int probe = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (probe < 0) throw InputError(path.string() + ": cannot write: " + reason(errno));
  ::close(probe);
  bool ok = false;
  try {
    ok = produce(temporary);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  std::error_code ec;
  const auto size = std::filesystem::file_size(temporary, ec);
  int saved = EIO;
  if (ok && !ec && size > 0 && sync_file(temporary)) {
    move_into_place(temporary, path);
    return;
  }
  if (ok && !ec && size > 0) saved = errno;
  std::remove(temporary.c_str());
  throw InputError(path.string() + ": cannot write: " +
                   (ok && !ec && size > 0 ? reason(saved) : std::string("the writer failed")));
}

}  // namespace rheomag
