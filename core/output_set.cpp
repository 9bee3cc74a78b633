// Staging folder inside the destination (same file system, so each rename is atomic); the
// renames run with the interruption deferred, so a signal never leaves half a set.

#include "core/output_set.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <set>
#include <system_error>
#include <utility>
#include <vector>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/finite_output.hpp"
#include "core/interrupt.hpp"

namespace rheomag {
namespace {

std::string reason(int error) {
  return std::generic_category().message(error);
}

// fsync of a folder, so the renames into it survive a crash (best effort).
void sync_folder(const std::filesystem::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

}  // namespace

OutputSet::OutputSet(std::filesystem::path dir, std::string what, Folder folder)
    : dir_(std::move(dir)), what_(std::move(what)) {
  if (dir_.empty()) dir_ = ".";
  std::error_code ec;
  if (folder == Folder::must_exist) {
    if (!std::filesystem::is_directory(dir_, ec))
      throw InputError(
          what_ + ": cannot write into " + dir_.string() + ": " +
          (std::filesystem::exists(dir_, ec) ? "not a folder" : "No such file or directory"));
  } else {
    std::filesystem::create_directories(dir_, ec);
    if (ec || !std::filesystem::is_directory(dir_))
      throw InputError(what_ + " " + dir_.string() + ": cannot create the folder (" +
                       (ec ? ec.message() : std::string("a file of that name exists")) + ")");
  }
  staging_ = dir_ / (".rheomag-staging-" + std::to_string(static_cast<long>(::getpid())));
  cleanup_ = std::make_unique<InterruptCleanupFile>(staging_);
  std::filesystem::remove_all(staging_, ec);  // a leftover of a killed run with this pid
  if (!std::filesystem::create_directory(staging_, ec) || ec)
    throw InputError(what_ + " " + dir_.string() + ": cannot write: " +
                     (ec ? ec.message() : std::string("the staging folder exists")));
}

OutputSet::~OutputSet() {
  std::error_code ignored;
  std::filesystem::remove_all(staging_, ignored);
}

std::filesystem::path OutputSet::staged(const std::string& file_name) const {
  return staging_ / file_name;
}

void OutputSet::write(const std::string& file_name,
                      const std::function<void(const std::filesystem::path&)>& writer) const {
  // The staging folder is an implementation detail: messages name the file where it was going.
  const auto destination_named = [&](std::string message) {
    const std::string from = staged(file_name).string(), to = (dir_ / file_name).string();
    for (std::size_t at = message.find(from); at != std::string::npos;
         at = message.find(from, at + to.size()))
      message.replace(at, from.size(), to);
    return message;
  };
  try {
    writer(staged(file_name));
  } catch (const NonFiniteOutputError& e) {
    throw NonFiniteOutputError(destination_named(e.what()));
  } catch (const InputError& e) {
    throw InputError(destination_named(e.what()));
  }
}

void OutputSet::commit(const std::function<bool(const std::string&)>& stale) {
  if (committed_) return;
  std::vector<std::string> names;
  for (const auto& entry : std::filesystem::directory_iterator(staging_))
    if (entry.is_regular_file()) names.push_back(entry.path().filename().string());
  // Every destination must be replaceable before anything moves.
  for (const std::string& name : names) check_output_path(dir_ / name, what_);
  const std::set<std::string> fresh(names.begin(), names.end());
  {
    const InterruptDeferral whole_set;
    for (const std::string& name : names) {
      const std::filesystem::path from = staging_ / name, to = dir_ / name;
      if (std::rename(from.c_str(), to.c_str()) != 0)
        throw InputError(to.string() + ": cannot write: " + reason(errno));
    }
    if (stale) {
      std::error_code ec;
      for (const auto& entry : std::filesystem::directory_iterator(dir_, ec)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && !fresh.count(name) && stale(name))
          std::filesystem::remove(entry.path(), ec);
      }
    }
    sync_folder(dir_);
  }
  committed_ = true;
}

}  // namespace rheomag
