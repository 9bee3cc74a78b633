#pragma once
// SIGINT and SIGTERM end the process at any phase without a crash and without leftovers: the
// signal handler only wakes a watcher thread (a self-pipe); the watcher kills the worker
// processes, removes the temporaries of output files being written and ends the process with
// _exit(128 + signal), running no destructor while other threads still work.

#include <sys/types.h>

#include <filesystem>

namespace rheomag {

/// Installs the handlers of SIGINT and SIGTERM and starts the watcher thread (once; later calls
/// do nothing). The CLI calls it at start-up; a library never does. A code section that handles
/// the signals itself (a sweep keeping its finished rows) may replace the handlers and restore
/// them afterwards.
void install_interrupt_handling();

/// True once install_interrupt_handling ran.
bool interrupt_handling_installed();

/// Registers a file (or a scratch folder with everything in it) to be removed when the process is
/// interrupted, for the lifetime of the object: a temporary beside an output file. Register
/// before the file is created, so no interruption can leave it behind.
class InterruptCleanupFile {
 public:
  explicit InterruptCleanupFile(const std::filesystem::path& path);
  ~InterruptCleanupFile();
  InterruptCleanupFile(const InterruptCleanupFile&) = delete;
  InterruptCleanupFile& operator=(const InterruptCleanupFile&) = delete;

 private:
  int slot_ = -1;
};

/// Holds back the end of an interrupted process for its lifetime: a signal that arrives meanwhile
/// ends the process only afterwards. For a short section that must not be cut in half (renaming
/// a set of output files into place); it must not create or release an InterruptCleanupFile.
class InterruptDeferral {
 public:
  InterruptDeferral();
  ~InterruptDeferral();
  InterruptDeferral(const InterruptDeferral&) = delete;
  InterruptDeferral& operator=(const InterruptDeferral&) = delete;
};

/// fork() for a worker process (TetGen): signals are blocked around the fork, the child gets
/// the default SIGINT/SIGTERM actions (it runs no watcher), and the parent registers the child
/// to be killed (SIGKILL) if the parent is interrupted. Returns what fork returns.
pid_t fork_worker_process();

/// Unregisters a child of fork_worker_process once it was waited for.
void release_worker_process(pid_t child);

}  // namespace rheomag
