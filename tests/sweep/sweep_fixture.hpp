#pragma once
// Shared helpers of the sweep tests: scratch directories, sweep files over the tiny test valve,
// reading files and running the rheomag CLI as a child process.

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace rheomag::sweep::testing {

/// The coarse P1 annular valve every sweep test uses as base case.
inline std::filesystem::path tiny_valve() {
  return std::filesystem::path(RHEOMAG_SOURCE_DIR) / "tests/optimise/data/tiny_annular_valve.toml";
}

/// Removes the scratch directories of a test program when it ends.
struct ScratchCleanup {
  std::vector<std::filesystem::path> dirs;
  ~ScratchCleanup() {
    std::error_code ignored;
    for (const auto& d : dirs) std::filesystem::remove_all(d, ignored);
  }
};

/// A fresh empty directory under the system temp directory (removed at exit).
inline std::filesystem::path scratch_dir(const std::string& name) {
  static ScratchCleanup cleanup;
  std::string pattern =
      (std::filesystem::temp_directory_path() / ("rheomag-" + name + "-XXXXXX")).string();
  const std::filesystem::path dir = ::mkdtemp(pattern.data());
  cleanup.dirs.push_back(dir);
  return dir;
}

/// Writes `text` to `dir/name` and returns the path.
inline std::filesystem::path write_file(const std::filesystem::path& dir, const std::string& name,
                                        const std::string& text) {
  std::ofstream(dir / name) << text;
  return dir / name;
}

/// The whole content of a file ("" if it cannot be read).
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The lines of a text (without newlines).
inline std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

/// A sweep file over the tiny valve: [sweep] body lines (after base) and the [[axis]] tables.
inline std::string sweep_text(const std::string& sweep_lines, const std::string& axes,
                              const std::string& output = "csv = \"results.csv\"\n") {
  return "[sweep]\nbase = \"" + tiny_valve().string() + "\"\n" + sweep_lines + "\n" + axes +
         "\n[output]\n" + output;
}

/// Starts the program all[0] (searched in PATH) with stdout and stderr redirected to files;
/// returns its pid (-1 if it could not be started).
inline pid_t start_program(std::vector<std::string> all, const std::filesystem::path& out,
                           const std::filesystem::path& err) {
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, out.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, err.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  if (posix_spawnp(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid = -1;
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

/// Starts `rheomag args...` with stdout and stderr redirected to files; returns its pid.
inline pid_t start_cli(const std::vector<std::string>& args, const std::filesystem::path& out,
                       const std::filesystem::path& err) {
  std::vector<std::string> all{RHEOMAG_BINARY};
  all.insert(all.end(), args.begin(), args.end());
  return start_program(all, out, err);
}

/// Exit code of a finished child (128 + signal if it was killed).
inline int wait_exit(pid_t pid) {
  if (pid < 0) return -1;
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (WIFSIGNALED(status)) return 128 + WTERMSIG(status);
  return WEXITSTATUS(status);
}

/// Result of a CLI run.
struct CliRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

/// Runs `rheomag args...` to completion (output captured in `dir`).
inline CliRun run_cli(const std::vector<std::string>& args, const std::filesystem::path& dir) {
  const pid_t pid = start_cli(args, dir / "cli.out", dir / "cli.err");
  CliRun run;
  run.exit_code = wait_exit(pid);
  run.out = read_text(dir / "cli.out");
  run.err = read_text(dir / "cli.err");
  return run;
}

}  // namespace rheomag::sweep::testing
