#pragma once
// Running the built rheomag binary (RHEOMAG_BINARY) from a test: exit code, stdout and stderr.

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

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

}  // namespace rheomag::cli_test
