#pragma once
// Running the built rheomag binary (RHEOMAG_BINARY) from a test: exit code, stdout and stderr.

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace rheomag::cli_test {

/// Exit code (-1 if the process did not exit normally), stdout and stderr of one CLI run.
struct CliRun {
  int code = -1;
  std::string out, err;
};

/// Runs `rheomag ARGS` through the shell (ARGS is shell text: quote what needs quoting), in the
/// directory `dir` when one is given.
inline CliRun run_rheomag(const std::string& args, const std::filesystem::path& dir = {}) {
  static int serial = 0;
  const std::filesystem::path err_file =
      std::filesystem::temp_directory_path() /
      ("rheomag_test_err_" + std::to_string(::getpid()) + "_" + std::to_string(++serial));
  const std::string command = (dir.empty() ? "" : "cd '" + dir.string() + "' && ") + "'" +
                              RHEOMAG_BINARY + "' " + args + " 2>'" + err_file.string() + "'";
  CliRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  while (const std::size_t got = std::fread(buffer, 1, sizeof buffer, pipe))
    run.out.append(buffer, got);
  const int status = pclose(pipe);
  run.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream err(err_file);
  run.err.assign(std::istreambuf_iterator<char>(err), {});
  std::filesystem::remove(err_file);
  return run;
}

/// Starts rheomag with `args` in `dir` (a child process, not waited for), stdout and stderr into
/// out.txt and err.txt there; for tests that signal a running command.
inline pid_t start_rheomag(const std::filesystem::path& dir, const std::vector<std::string>& args) {
  std::filesystem::remove(dir / "err.txt");  // not the last run's lines
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::chdir(dir.c_str()) != 0) ::_exit(120);
    const int out = ::open("out.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = ::open("err.txt", O_WRONLY | O_CREAT | O_TRUNC, 0644);
    ::dup2(out, STDOUT_FILENO);
    ::dup2(err, STDERR_FILENO);
    std::vector<char*> argv{const_cast<char*>(RHEOMAG_BINARY)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    ::execv(RHEOMAG_BINARY, argv.data());
    ::_exit(121);
  }
  return pid;
}

/// True once process `pid` catches `signal_number` (SigCgt of /proc/PID/status: rheomag's
/// handlers are installed at the start of main; before, the default action would end it).
inline bool catches_signal(pid_t pid, int signal_number) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("SigCgt:", 0) == 0)
      return (std::stoull(line.substr(7), nullptr, 16) >> (signal_number - 1) & 1) != 0;
  return false;
}

}  // namespace rheomag::cli_test
