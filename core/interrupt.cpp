// The self-pipe watcher of SIGINT/SIGTERM. The handler does only async-signal-safe work (store
// the signal, write one byte); the watcher is an ordinary thread.

#include "core/interrupt.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstring>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace rheomag {
namespace {

std::atomic<int> g_interrupt_signal{0};
int g_interrupt_pipe[2] = {-1, -1};
std::once_flag g_interrupt_once;
std::atomic<bool> g_interrupt_installed{false};

/// What the watcher cleans up: temporaries of outputs and worker processes.
struct InterruptRegistry {
  std::mutex mutex;
  std::map<int, std::string> files;
  int next_slot = 0;
  std::vector<pid_t> children;
};

InterruptRegistry& interrupt_registry() {
  static InterruptRegistry* registry = new InterruptRegistry;  // never destroyed: the watcher
  return *registry;                                            // may use it during exit
}

extern "C" void on_interrupt_signal(int signal_number) {
  const int saved = errno;
  int expected = 0;
  g_interrupt_signal.compare_exchange_strong(expected, signal_number);
  const char byte = 1;
  [[maybe_unused]] const ssize_t n = ::write(g_interrupt_pipe[1], &byte, 1);
  errno = saved;
}

void write_stderr(const char* text) {
  std::size_t left = std::strlen(text);
  while (left > 0) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    text += n;
    left -= static_cast<std::size_t>(n);
  }
}

[[noreturn]] void finish_interrupted() {
  const int signal_number = g_interrupt_signal.load();
  InterruptRegistry& registry = interrupt_registry();
  registry.mutex.lock();  // held until _exit: no new temporary or worker can appear
  for (const pid_t child : registry.children) ::kill(child, SIGKILL);
  // Other threads keep running until _exit and release any lock they hold, so the watcher may
  // allocate here (remove_all of a scratch folder).
  for (const auto& [slot, path] : registry.files) {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
  write_stderr(signal_number == SIGINT ? "rheomag: interrupted (SIGINT)"
                                       : "rheomag: terminated (SIGTERM)");
  write_stderr(
      "; stopped: no output file was left half-written (an output being written was not "
      "replaced)\n");
  ::_exit(128 + signal_number);
}

void watch_for_interrupt() {
  char byte = 0;
  while (true) {
    const ssize_t n = ::read(g_interrupt_pipe[0], &byte, 1);
    if (n == 1) finish_interrupted();
    if (n < 0 && errno == EINTR) continue;
    return;  // the pipe failed: the default actions stay the fallback
  }
}

void start_interrupt_handling() {
  if (::pipe2(g_interrupt_pipe, O_CLOEXEC) != 0) return;
  ::fcntl(g_interrupt_pipe[1], F_SETFL, O_NONBLOCK);
  std::thread(watch_for_interrupt).detach();
  struct sigaction action {};
  action.sa_handler = on_interrupt_signal;
  sigemptyset(&action.sa_mask);
  action.sa_flags = SA_RESTART;
  ::sigaction(SIGINT, &action, nullptr);
  ::sigaction(SIGTERM, &action, nullptr);
  g_interrupt_installed.store(true);
}

}  // namespace

void install_interrupt_handling() {
  std::call_once(g_interrupt_once, start_interrupt_handling);
}

bool interrupt_handling_installed() {
  return g_interrupt_installed.load();
}

InterruptCleanupFile::InterruptCleanupFile(const std::filesystem::path& path) {
  InterruptRegistry& registry = interrupt_registry();
  std::lock_guard lock(registry.mutex);
  slot_ = registry.next_slot++;
  registry.files.emplace(slot_, path.string());
}

InterruptCleanupFile::~InterruptCleanupFile() {
  InterruptRegistry& registry = interrupt_registry();
  std::lock_guard lock(registry.mutex);
  registry.files.erase(slot_);
}

InterruptDeferral::InterruptDeferral() {
  interrupt_registry().mutex.lock();  // the watcher takes it before it ends the process
}

InterruptDeferral::~InterruptDeferral() {
  interrupt_registry().mutex.unlock();
}

pid_t fork_worker_process() {
  sigset_t interrupts, previous;
  sigemptyset(&interrupts);
  sigaddset(&interrupts, SIGINT);
  sigaddset(&interrupts, SIGTERM);
  InterruptRegistry& registry = interrupt_registry();
  // The registry lock keeps the watcher from exiting between the fork and the registration
  // (it would leave the child running); signals stay blocked so the child starts with them
  // pending at the default action, never in the parent's handler.
  std::lock_guard lock(registry.mutex);
  registry.children.reserve(registry.children.size() + 1);
  ::pthread_sigmask(SIG_BLOCK, &interrupts, &previous);
  const pid_t child = ::fork();
  if (child == 0) {
    struct sigaction fallback {};
    fallback.sa_handler = SIG_DFL;
    sigemptyset(&fallback.sa_mask);
    ::sigaction(SIGINT, &fallback, nullptr);
    ::sigaction(SIGTERM, &fallback, nullptr);
    ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
    return 0;
  }
  if (child > 0) registry.children.push_back(child);
  ::pthread_sigmask(SIG_SETMASK, &previous, nullptr);
  return child;
}

void release_worker_process(pid_t child) {
  InterruptRegistry& registry = interrupt_registry();
  std::lock_guard lock(registry.mutex);
  std::erase(registry.children, child);
}

}  // namespace rheomag
