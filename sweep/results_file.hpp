#pragma once
// The results CSV of a sweep on disk: created with its header atomically, rows appended one
// complete line per write() on an O_APPEND descriptor followed by fsync (so a killed sweep keeps
// every finished row and no torn row is ever taken for a finished one), resumed by reading the
// rows already there, and rewritten sorted by design id (temp file + rename) at the end.

#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <string>

namespace rheomag::sweep {

/// Rows of a results file by design id (each row with its newline).
using RowsById = std::map<long long, std::string>;

/// Expected start of the row of design `id` ("" if `id` does not belong to this run).
using RowPrefix = std::function<std::string(long long id)>;

/// Reads the finished rows of an existing results file. The header must equal `header`; every
/// complete line must start with prefix(id) of its id (otherwise the file belongs to another
/// sweep: InputError naming file and line). An incomplete last line (a write cut short) and
/// repeated ids are dropped; `repaired` tells whether anything was dropped.
RowsById read_finished_rows(const std::filesystem::path& path, const std::string& header,
                            const RowPrefix& prefix, bool& repaired);

/// Header plus rows in id order, written atomically.
void write_sorted(const std::filesystem::path& path, const std::string& header,
                  const RowsById& rows);

/// Appends complete rows to a results file (thread-safe).
class RowAppender {
 public:
  /// Opens `path` (which must exist) with O_APPEND; InputError if that fails.
  explicit RowAppender(const std::filesystem::path& path);
  ~RowAppender();
  RowAppender(const RowAppender&) = delete;
  RowAppender& operator=(const RowAppender&) = delete;
  /// Writes the row with one write() and fsyncs; InputError (disk full, I/O error) otherwise.
  void append(const std::string& row);

 private:
  std::filesystem::path path_;
  int fd_ = -1;
  std::mutex mutex_;
};

/// Throws InputError unless `dir` exists or can be created and a file can be written in it
/// (probed with a temporary file that is removed again).
void require_writable_directory(const std::filesystem::path& dir);

/// Throws InputError when `bytes` exceed the space available at `dir` (std::filesystem::space),
/// naming both amounts and `what` is being written.
void require_free_space(const std::filesystem::path& dir, double bytes, const std::string& what);

}  // namespace rheomag::sweep
