// rheomag: command-line entry point. Subcommands live in app/cmd_*.cpp.

#include <SuiteSparse_config.h>
#include <glog/logging.h>
#include <vtkLogger.h>
#include <vtkObject.h>
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <new>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "app/command.hpp"
#include "app/finite_stdout.hpp"
#include "case/case_key.hpp"
#include "core/blas_threads.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "core/version.hpp"
#include "lumped/recording_io.hpp"
#include "magnetostatics/assembly.hpp"

namespace rheomag::app {

namespace {
std::vector<CommandSetup>& registry() {
  static std::vector<CommandSetup> commands;
  return commands;
}
}  // namespace

bool register_command(CommandSetup setup) {
  registry().push_back(std::move(setup));
  return true;
}

namespace {

/// The first sentence of a command's description (abbreviations such as "e.g." do not end it),
/// or its first clause when the sentence is longer than a line: the root --help never cuts a
/// description off with "..." (tests/app checks it).
std::string first_sentence(const std::string& text) {
  std::size_t end = 0;
  while (true) {
    end = text.find('.', end);
    if (end == std::string::npos) return text.substr(0, text.find('\n'));
    const bool abbreviation = (end >= 3 && text.compare(end - 3, 3, "e.g") == 0) ||
                              (end >= 3 && text.compare(end - 3, 3, "i.e") == 0) ||
                              (end >= 3 && text.compare(end - 3, 3, " eq") == 0) ||
                              (end >= 1 && text[end - 1] == '*');
    if (!abbreviation && (end + 1 == text.size() || text[end + 1] == ' ' || text[end + 1] == '\n'))
      break;
    ++end;
  }
  std::string sentence = text.substr(0, end);
  for (char& c : sentence)
    if (c == '\n') c = ' ';
  // A sentence longer than a line of the root --help is summarised by its first clause (up to
  // ':', ';' or a parenthesis), never cut off; the command's own --help shows the whole text.
  constexpr std::size_t kWidth = 90;
  if (sentence.size() > kWidth) {
    std::size_t clause = std::string::npos;
    for (const char* mark : {": ", "; ", " (", ", "})
      clause = std::min(clause, sentence.find(mark, 10));
    if (clause != std::string::npos) sentence.resize(clause);
  }
  return sentence;
}

}  // namespace

lumped::Recording load_recording(const std::string& csv_path) {
  lumped::Recording rec = lumped::read_recording(csv_path);
  for (const std::string& w : rec.warnings) std::cerr << "rheomag: warning: " << w << "\n";
  return rec;
}

cases::Case load_case(const std::string& path, const std::vector<std::string>& settings) {
  cases::Case c = cases::with_settings(cases::load_case(path), settings, "--set");
  for (const std::string& w : c.problem.warnings) std::cerr << "rheomag: warning: " << w << "\n";
  return c;
}

std::vector<std::pair<std::string, double>> parse_holds(const std::vector<std::string>& holds) {
  std::vector<std::pair<std::string, double>> out;
  for (const std::string& text : holds) {
    const auto eq = text.find('=');
    double value = 0.0;
    std::size_t used = 0;
    if (eq != std::string::npos && eq > 0 && eq + 1 < text.size()) {
      try {
        value = std::stod(text.substr(eq + 1), &used);
      } catch (const std::exception&) {
        used = 0;
      }
    }
    if (eq == std::string::npos || eq == 0 || used == 0 || used != text.size() - eq - 1 ||
        !std::isfinite(value))
      throw InputError(
          "--hold: expected NAME=VALUE (a parameter of the model and a finite "
          "number in SI units, e.g. inertance=20), got \"" +
          text + "\"");
    out.emplace_back(text.substr(0, eq), value);
  }
  return out;
}

void setup_commands(CLI::App& root) {
  for (auto& setup : registry()) setup(root);
  // The root --help lists each command by its first sentence; the whole text is shown below the
  // options of the command's own --help.
  for (CLI::App* command : root.get_subcommands([](CLI::App*) { return true; })) {
    const std::string full = command->get_description();
    const std::string summary = first_sentence(full);
    if (summary == full) continue;
    command->description(summary);
    command->footer(full);
  }
}

/// Keeps third-party logging (Ceres reports failed trial steps through glog, VTK failed writes) off
/// the user's stderr: rheomag reports what matters through its own messages and exit codes.
void silence_third_party_logging() {
  FLAGS_minloglevel = google::GLOG_FATAL;
  // VTK's writers report a failed write (a full disk) on stderr; the atomic writer checks their
  // status and rheomag names the file in its own message.
  vtkObject::GlobalWarningDisplayOff();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  // CHOLMOD prints its errors ("CHOLMOD error: out of memory") with printf on stdout, where they
  // broke --json; the solvers turn its status into rheomag's own message and exit code.
#if SUITESPARSE_MAIN_VERSION >= 7
  SuiteSparse_config_printf_func_set(nullptr);
#else
  SuiteSparse_config.printf_func = nullptr;
#endif
}

}  // namespace rheomag::app

int main(int argc, char** argv) {
  CLI::App root{
      "rheomag: magnetorheological valve and damper design.\n"
      "Axisymmetric nonlinear magnetostatics (the FEMM step), MR-fluid gap flow, lumped "
      "dynamics,\nidentification, diagnosis and optimisation. Run 'rheomag COMMAND --help' "
      "for each command."};
  root.require_subcommand(1);
  root.set_version_flag("--version", "rheomag " + rheomag::project_version() + " (git " +
                                         rheomag::git_revision() + ")");
  // SIGINT/SIGTERM end any command with 130/143, temporaries removed (core/interrupt.hpp).
  rheomag::install_interrupt_handling();
  rheomag::prefer_single_threaded_blas();
  rheomag::app::silence_third_party_logging();
  // Element assembly on OpenMP threads only when OMP_NUM_THREADS is set (the library default is
  // serial; docs/performance.md, "Threads").
  if (std::getenv("OMP_NUM_THREADS") != nullptr) rheomag::magnetostatics::set_assembly_threads(0);
  rheomag::app::setup_commands(root);
  std::string command_line = "rheomag";
  for (int k = 1; k < argc; ++k) command_line += std::string(" ") + argv[k];
  // Every line a command prints passes the non-finite guard (app/finite_stdout.hpp).
  rheomag::app::GuardedStdout guarded;
  try {
    root.parse(argc, argv);
    guarded.check(command_line);
  } catch (const CLI::ParseError& e) {
    int code = root.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const rheomag::InputError& e) {
    std::cerr << "rheomag: error: " << e.what() << "\n";
    return 2;
  } catch (const rheomag::NonFiniteOutputError& e) {
    guarded.finish();
    const std::string what = e.what();
    std::cerr << "rheomag: result is not a finite number: " << what
              << (what.find("produced by: ") == std::string::npos ? "; produced by: " + command_line
                                                                  : std::string())
              << "\n";
    return 3;
  } catch (const rheomag::ConvergenceError& e) {
    std::cerr << "rheomag: solver did not converge: " << e.what() << "\n";
    return 3;
  } catch (const std::bad_alloc&) {
    // Bounds are checked before the work where they can be estimated (input file sizes, mesh
    // sizes, --max-memory); what still runs out is the input's size, not a defect: exit 2.
    std::cerr << "rheomag: error: out of memory: the input needs more memory than is available "
                 "here ("
              << command_line
              << "); expected a smaller input (coarser mesh, fewer samples or designs) or a "
                 "machine with more memory\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "rheomag: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
