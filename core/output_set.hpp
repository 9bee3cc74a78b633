#pragma once
// A set of output files that replaces its previous version as a whole (a recording and its
// sidecar, a diagnosis folder, a VTK time series, a folder of pictures): every file is written
// into a staging folder inside the destination first, and only when all of them are written are
// they renamed into place. A failure (a full disk, a bad value, an interruption) leaves the old
// set whole and no staging folder behind.

#include <filesystem>
#include <functional>
#include <memory>
#include <string>

namespace rheomag {

class InterruptCleanupFile;

/// Staging folder for a set of output files bound for one folder.
class OutputSet {
 public:
  /// Creates `dir` if missing and a hidden staging folder inside it; InputError naming `what`
  /// (the option, e.g. "--out") and the system's reason when either cannot be created.
  OutputSet(std::filesystem::path dir, std::string what);
  ~OutputSet();
  OutputSet(const OutputSet&) = delete;
  OutputSet& operator=(const OutputSet&) = delete;

  /// Where to write the set's file `file_name` (a plain name, no folder): inside the staging
  /// folder. Write it with write_file_atomically or any writer taking a file name.
  std::filesystem::path staged(const std::string& file_name) const;

  /// The destination folder.
  const std::filesystem::path& folder() const { return dir_; }

  /// Renames every staged file into the destination, replacing files of the same names, then
  /// removes the destination's files for which `stale(file_name)` is true and that the new set
  /// does not hold (the old set's leftovers, e.g. a longer series' last states). InputError,
  /// with nothing replaced, when a destination name is a folder or special file.
  void commit(const std::function<bool(const std::string&)>& stale = {});

 private:
  std::filesystem::path dir_;
  std::filesystem::path staging_;
  std::string what_;
  std::unique_ptr<InterruptCleanupFile> cleanup_;
  bool committed_ = false;
};

}  // namespace rheomag
