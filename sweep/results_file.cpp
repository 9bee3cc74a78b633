#include "sweep/results_file.hpp"
#include "core/input_file.hpp"

#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace rheomag::sweep {

namespace {

std::string system_error(const std::string& what, const std::filesystem::path& path) {
  return what + " '" + path.string() + "': " + std::strerror(errno);
}

/// Writes all of `data` to `fd` (one write() unless the kernel writes less, e.g. disk full).
bool write_all(int fd, const std::string& data) {
  std::size_t done = 0;
  while (done < data.size()) {
    const ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    done += static_cast<std::size_t>(n);
  }
  return true;
}

std::string human_bytes(double bytes) {
  const char* units[] = {"B", "kB", "MB", "GB", "TB", "PB"};
  int u = 0;
  while (bytes >= 1000.0 && u < 5) {
    bytes /= 1000.0;
    ++u;
  }
  char buffer[48];
  std::snprintf(buffer, sizeof buffer, "%.3g %s", bytes, units[u]);
  return buffer;
}

}  // namespace

RowsById read_finished_rows(const std::filesystem::path& path, const std::string& header,
                            const RowPrefix& prefix, bool& repaired) {
  repaired = false;
  const std::string text = read_input_file(path);
  const std::string file = path.string();
  if (text.compare(0, header.size(), header) != 0) {
    throw InputError(file +
                     ": exists with other columns than this sweep writes (a different "
                     "sweep file?); remove it or choose another --out directory");
  }
  RowsById rows;
  std::size_t start = header.size();
  int line_number = 1;
  while (start < text.size()) {
    ++line_number;
    const std::size_t end = text.find('\n', start);
    if (end == std::string::npos) {  // a row cut short by a crash mid-write: not finished
      repaired = true;
      break;
    }
    const std::string line = text.substr(start, end + 1 - start);
    start = end + 1;
    long long id = -1;
    std::size_t digits = 0;
    while (digits < line.size() && line[digits] >= '0' && line[digits] <= '9') ++digits;
    if (digits > 0 && digits < 19 && line[digits] == ',') id = std::stoll(line.substr(0, digits));
    const std::string expected = id >= 0 ? prefix(id) : std::string();
    if (expected.empty() || line.compare(0, expected.size(), expected) != 0) {
      throw InputError(file + ":" + std::to_string(line_number) +
                       ": this row does not belong to this sweep (design id or input values "
                       "differ; was the sweep file changed?); remove the file or choose another "
                       "--out directory");
    }
    if (!rows.emplace(id, line).second) repaired = true;
  }
  return rows;
}

void write_sorted(const std::filesystem::path& path, const std::string& header,
                  const RowsById& rows) {
  std::string content = header;
  for (const auto& [id, row] : rows) content += row;
  write_file_atomically(path, content);
}

RowAppender::RowAppender(const std::filesystem::path& path) : path_(path) {
  fd_ = ::open(path.c_str(), O_WRONLY | O_APPEND | O_CLOEXEC);
  if (fd_ < 0) throw InputError(system_error("cannot open for appending", path));
}

RowAppender::~RowAppender() {
  if (fd_ >= 0) ::close(fd_);
}

void RowAppender::append(const std::string& row) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!write_all(fd_, row) || ::fsync(fd_) != 0) {
    throw InputError(system_error("cannot append a row to", path_) +
                     " (finished rows are kept; free space and run the same command again)");
  }
}

void require_writable_directory(const std::filesystem::path& dir) {
  std::error_code error;
  std::filesystem::create_directories(dir, error);
  if (error || !std::filesystem::is_directory(dir)) {
    throw InputError("output directory '" + dir.string() + "' cannot be created: " +
                     (error ? error.message() : "a file of that name exists"));
  }
  std::string probe = (dir / ".rheomag-write-probe-XXXXXX").string();
  const int fd = ::mkstemp(probe.data());
  if (fd < 0) throw InputError(system_error("output directory cannot be written:", dir));
  const bool ok = write_all(fd, "x") && ::fsync(fd) == 0;
  ::close(fd);
  std::remove(probe.c_str());
  if (!ok) throw InputError(system_error("output directory cannot be written:", dir));
}

void require_free_space(const std::filesystem::path& dir, double bytes, const std::string& what) {
  std::error_code error;
  const std::filesystem::space_info space = std::filesystem::space(dir, error);
  if (error) return;  // unknown (e.g. a special file system): nothing to compare against
  if (bytes > static_cast<double>(space.available)) {
    throw InputError("the sweep is too large for the disk: " + what + " needs about " +
                     human_bytes(bytes) + " but only " +
                     human_bytes(static_cast<double>(space.available)) + " are free at '" +
                     dir.string() +
                     "'; free space, choose another --out or split the sweep "
                     "(--shard)");
  }
}

}  // namespace rheomag::sweep
