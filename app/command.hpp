#pragma once
// Registry of CLI subcommands: each app/cmd_*.cpp registers itself at start-up.

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/finite_stdout.hpp"
#include "case/case_file.hpp"
#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "core/quantity_domain.hpp"
#include "core/units.hpp"
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

/// Loads a case (TOML or .fem) and applies the command's `--set KEY=VALUE` settings through the
/// typed key API (cases::with_settings): one implementation for every command that takes a case.
cases::Case load_case(const std::string& path, const std::vector<std::string>& settings);

/// Adds the repeatable `--set KEY=VALUE` option of a command that takes a case.
inline CLI::Option* add_set_option(CLI::App* cmd, std::vector<std::string>& settings) {
  return cmd
      ->add_option("--set", settings,
                   "Change one value of the case, KEY=VALUE (repeatable), e.g. --set "
                   "geometry.turns=800 --set geometry.gap_width=1.2mm: the case file's "
                   "keys and its template's parameters (docs/case-format.md); a length may carry "
                   "a unit")
      ->type_name("KEY=VALUE")
      ->allow_extra_args(false);  // one setting per --set: a case path after it stays the case
}

/// Adds the repeatable `--hold NAME=VALUE` option of the grey-box fits (`fit`, `fit-family`).
inline CLI::Option* add_hold_option(CLI::App* cmd, std::vector<std::string>& holds) {
  return cmd
      ->add_option("--hold", holds,
                   "Grey-box models: hold a parameter at a value instead of fitting it, "
                   "NAME=VALUE in SI units (repeatable), e.g. --hold inertance=20 for a fluid "
                   "inertance known from the geometry; reported as held")
      ->type_name("NAME=VALUE")
      ->allow_extra_args(false);
}

/// Adds the `--keep-inertance` flag of the grey-box fits (`fit`, `fit-family`).
inline CLI::Option* add_keep_inertance_flag(CLI::App* cmd, bool& keep) {
  return cmd->add_flag(
      "--keep-inertance", keep,
      "Damper model: fit the inertance even where it removes under 10 % of the residual "
      "energy (by default it is then held at 0 and reported so: slow tests cannot show a "
      "moving mass, and one fitted to them spoils predictions at higher frequencies)");
}

/// Adds the `--motion-lead auto|SECONDS` option of the grey-box fits (`fit`, `fit-family`):
/// "auto" or a number of seconds within +-0.1 s (exit 2 otherwise, before any fit).
inline CLI::Option* add_motion_lead_option(CLI::App* cmd, std::string& lead,
                                           const std::string& search) {
  return cmd
      ->add_option("--motion-lead", lead,
                   "[s] read the velocity (flow) drive this much later than recorded, v(t + "
                   "lead), against the displacement and the output, in the fit and in every "
                   "prediction: a velocity column that lags (a backward difference lags half a "
                   "sample, a filter more); stored in the model file. auto: the fit is refitted "
                   "(warm, 30 iterations) at -5 to 15 ms in 2.5 ms steps and the lead " +
                       search + " is kept")
      ->capture_default_str()
      ->check(CLI::Validator(
          [](std::string& value) {
            if (value == "auto") return std::string();
            char* end = nullptr;
            const double v = std::strtod(value.c_str(), &end);
            if (end == value.c_str() || *end != '\0')
              return "expected auto or a lead in seconds, got \"" + value + "\"";
            return Domain::between(-0.1, 0.1, "s").violation(v);
          },
          "auto|SECONDS"));
}

/// The --hold settings as (name, value) pairs; InputError "--hold: expected NAME=VALUE ..." for
/// one without '=', an empty name or a value that is not a finite number.
std::vector<std::pair<std::string, double>> parse_holds(const std::vector<std::string>& holds);

/// The help suffix of a quantity option: its SI unit and the units it accepts.
inline std::string unit_help(QuantityKind kind) {
  return " (units: " + accepted_units(kind) + "; " + std::string(si_unit(kind)) +
         " when none is written)";
}

/// Adds an option of comma-separated quantities of `kind`, each with an optional unit
/// ("--flow 1.5L/min,3L/min"), stored in SI; a bad unit exits 2 naming the option, the unit and
/// the units accepted (core/units.hpp).
inline CLI::Option* add_quantities(CLI::App* cmd, const std::string& name,
                                   std::vector<double>& values, QuantityKind kind,
                                   const std::string& help) {
  return cmd
      ->add_option_function<std::vector<std::string>>(
          name,
          [&values, kind, name](const std::vector<std::string>& texts) {
            values = parse_quantities(texts, kind, name);
          },
          help + unit_help(kind))
      ->delimiter(',')
      ->type_name("VALUES");
}

/// Adds an option of one quantity of `kind` with an optional unit ("--duration 50ms"), in SI;
/// `value` is a double or a std::optional<double> (absent: the case's or the command's default).
template <class Target>
inline CLI::Option* add_quantity(CLI::App* cmd, const std::string& name, Target& value,
                                 QuantityKind kind, const std::string& help) {
  return cmd
      ->add_option_function<std::string>(
          name,
          [&value, kind, name](const std::string& text) {
            value = parse_quantity(text, kind, name);
          },
          help + unit_help(kind))
      ->type_name("VALUE");
}

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
