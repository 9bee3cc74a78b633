// SIGINT/SIGTERM under install_interrupt_handling: the process ends with 128 + the signal, the
// registered temporaries are removed and the registered worker processes killed. Each case runs
// in a forked child so that the test process itself is never interrupted.

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <thread>

#include "core/interrupt.hpp"

namespace fs = std::filesystem;

namespace {

fs::path interrupt_scratch(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / ("rheomag_interrupt_" + name);
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

/// True when process `pid` no longer runs (absent or a zombie).
bool process_is_gone(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  if (!stat) return true;
  std::string text((std::istreambuf_iterator<char>(stat)), {});
  const std::size_t close = text.rfind(')');
  return close == std::string::npos || close + 2 >= text.size() || text[close + 2] == 'Z';
}

/// Runs `body` in a child process with interrupt handling installed and signals it with
/// `signal_number` after `body` wrote its marker file; the child's wait status.
template <class Body>
int status_of_interrupted_child(const fs::path& dir, int signal_number, Body body) {
  const pid_t child = ::fork();
  if (child == 0) {
    rheomag::install_interrupt_handling();
    body();
    std::ofstream(dir / "ready") << "1";
    while (true) ::pause();  // the watcher ends the process
  }
  for (int k = 0; k < 500 && !fs::exists(dir / "ready"); ++k)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  ::kill(child, signal_number);
  int status = 0;
  ::waitpid(child, &status, 0);
  return status;
}

}  // namespace

TEST(Interrupt, SigtermExits143AndRemovesRegisteredTemporaries) {
  const fs::path dir = interrupt_scratch("term");
  const int status = status_of_interrupted_child(dir, SIGTERM, [&] {
    static rheomag::InterruptCleanupFile temporary(dir / "out.csv.tmp-1");
    std::ofstream(dir / "out.csv.tmp-1") << "half a row";
    static rheomag::InterruptCleanupFile scratch(dir / "scratch");
    fs::create_directories(dir / "scratch");
    std::ofstream(dir / "scratch" / "segment0.dat") << "1 2";
    std::ofstream(dir / "kept.csv") << "a finished output";
  });
  ASSERT_TRUE(WIFEXITED(status)) << "ended by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 143);  // 128 + SIGTERM (15)
  EXPECT_FALSE(fs::exists(dir / "out.csv.tmp-1"));
  EXPECT_FALSE(fs::exists(dir / "scratch"));
  EXPECT_TRUE(fs::exists(dir / "kept.csv"));  // not registered: a finished output stays
  fs::remove_all(dir);
}

TEST(Interrupt, SigintExits130AndKillsRegisteredWorkers) {
  const fs::path dir = interrupt_scratch("int");
  const int status = status_of_interrupted_child(dir, SIGINT, [&] {
    const pid_t worker = rheomag::fork_worker_process();
    if (worker == 0) {
      std::ofstream(dir / "worker.pid") << ::getpid();
      while (true) ::pause();  // killed by the watcher of its parent
    }
    for (int k = 0; k < 500 && !fs::exists(dir / "worker.pid"); ++k)
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
  });
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 130);  // 128 + SIGINT (2)
  pid_t worker = 0;
  std::ifstream(dir / "worker.pid") >> worker;
  ASSERT_GT(worker, 0);
  // The worker was killed with SIGKILL (it is reparented: gone, or a zombie where the init
  // process of a container does not reap).
  bool gone = false;
  for (int k = 0; k < 200 && !gone; ++k) {
    gone = process_is_gone(worker);
    if (!gone) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_TRUE(gone) << "worker " << worker << " still runs";
  fs::remove_all(dir);
}

TEST(Interrupt, WorkerChildKeepsTheDefaultActions) {
  // A worker runs no watcher: in it, SIGTERM must act by default, not wait on a pipe nobody reads.
  rheomag::install_interrupt_handling();
  const pid_t worker = rheomag::fork_worker_process();
  if (worker == 0) {
    while (true) ::pause();
  }
  ::kill(worker, SIGTERM);
  int status = 0;
  ::waitpid(worker, &status, 0);
  rheomag::release_worker_process(worker);
  ASSERT_TRUE(WIFSIGNALED(status));
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
}
