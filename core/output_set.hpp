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
  /// What to do when the destination folder is missing.
  enum class Folder { create, must_exist };

  /// Creates a hidden staging folder inside `dir` (and `dir` itself if missing, with
  /// Folder::create: an output folder such as diagnose --out; a file's folder, such as the one of
  /// simulate --out REC.csv, must exist). InputError naming `what` (the option or file) and the
  /// system's reason otherwise.
  OutputSet(std::filesystem::path dir, std::string what, Folder folder = Folder::create);

  /// Runs `writer(staged(file_name))` (a writer of one file: write_file_atomically, VTK's, a
  /// figure's); an InputError it throws names the file's destination, not the staging folder.
  void write(const std::string& file_name,
             const std::function<void(const std::filesystem::path&)>& writer) const;
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
