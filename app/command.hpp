#pragma once
// Registry of CLI subcommands: each app/cmd_*.cpp registers itself at start-up.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <string>

#include "app/finite_stdout.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/quantity_domain.hpp"
#include "lumped/recording.hpp"

namespace rheomag::app {

/// Adds one subcommand (with its options and callback) to the root CLI application.
using CommandSetup = std::function<void(CLI::App& root)>;

/// Registers a subcommand; returns true so it can initialise a static variable.
bool register_command(CommandSetup setup);

/// Calls every registered setup on `root`.
void setup_commands(CLI::App& root);

/// Reads a recording (CSV + sidecar) and prints the reader's warnings on stderr.
lumped::Recording load_recording(const std::string& csv_path);

/// Validator of an output-file option: refuses an empty name and a target that is not a regular
/// file (a device node, a directory) when the command line is parsed, before any work is done.
inline CLI::Validator output_file() {
  return CLI::Validator(
      [](std::string& path) {
        try {
          check_output_path(path, "output file");
        } catch (const InputError& e) {
          return std::string(e.what());
        }
        return std::string();
      },
      "FILE");
}

/// Validator of a numeric option's domain, worded as every reader's ("--jobs: expected a whole
/// number >= 0, got -1"). CLI11's own range checks (CLI::Range, PositiveNumber, NonNegativeNumber)
/// print an open end as the largest double in full, 309 digits; app/ uses this one instead.
inline CLI::Validator in_domain(const Domain& domain) {
  return CLI::Validator(
      [domain](std::string& value) {
        char* end = nullptr;
        const double v = std::strtod(value.c_str(), &end);
        if (end == value.c_str() || *end != '\0') return std::string();  // the conversion says it
        return domain.violation(v);
      },
      domain.describe());
}

/// Validator of an output file that is written only after long work: output_file, plus a folder
/// that exists and can be written to, so a typo fails at once rather than after the solve.
inline CLI::Validator output_file_in_writable_folder() {
  return output_file() & CLI::Validator(
                             [](std::string& path) {
                               std::filesystem::path folder =
                                   std::filesystem::path(path).parent_path();
                               if (folder.empty()) folder = ".";
                               if (!std::filesystem::is_directory(folder))
                                 return "folder " + folder.string() + " does not exist";
                               if (::access(folder.c_str(), W_OK) != 0)
                                 return "folder " + folder.string() + " is not writable";
                               return std::string();
                             },
                             "");
}

/// Validator of an option whose value names a file, folder, range or choice: an empty value (a
/// script's unset variable, `--out "$DIR"`) would read as the option's absence and be ignored
/// without a word (nothing written, exit 0).
inline CLI::Validator non_empty() {
  return CLI::Validator(
      [](std::string& value) {
        return value.empty() ? std::string(
                                   "expected a value, got \"\" (an empty value is not "
                                   "the option's absence)")
                             : std::string();
      },
      "");
}

}  // namespace rheomag::app
