// rheomag: command-line entry point. Subcommands live in app/cmd_*.cpp.

#include <dlfcn.h>

#include <CLI/CLI.hpp>
#include <cstdlib>
#include <iostream>
#include <vector>

#include "app/command.hpp"
#include "mesh/error.hpp"

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

void setup_commands(CLI::App& root) {
  for (auto& setup : registry()) setup(root);
}

/// Makes OpenBLAS (when it is the system BLAS behind CHOLMOD) single-threaded unless the user
/// set OPENBLAS_NUM_THREADS: at rheomag's problem sizes a second BLAS thread gains little, and
/// with parallel sweep workers or a busy machine its spinning threads cost 20x (see
/// docs/performance.md, "Threads"). Looked up at run time: other BLAS builds lack the symbol.
void prefer_single_threaded_blas() {
  if (std::getenv("OPENBLAS_NUM_THREADS") != nullptr) return;
  using SetThreads = void (*)(int);
  if (auto set = reinterpret_cast<SetThreads>(dlsym(RTLD_DEFAULT, "openblas_set_num_threads")))
    set(1);
}

}  // namespace rheomag::app

int main(int argc, char** argv) {
  CLI::App root{
      "rheomag: magnetorheological valve and damper design.\n"
      "Axisymmetric nonlinear magnetostatics (the FEMM step), MR-fluid gap flow, lumped "
      "dynamics,\nidentification, diagnosis and optimisation. Run 'rheomag COMMAND --help' "
      "for each command."};
  root.require_subcommand(1);
  rheomag::app::prefer_single_threaded_blas();
  rheomag::app::setup_commands(root);
  try {
    root.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    int code = root.exit(e);
    return code == 0 ? 0 : 2;
  } catch (const rheomag::InputError& e) {
    std::cerr << "rheomag: error: " << e.what() << "\n";
    return 2;
  } catch (const rheomag::ConvergenceError& e) {
    std::cerr << "rheomag: solver did not converge: " << e.what() << "\n";
    return 3;
  } catch (const std::exception& e) {
    std::cerr << "rheomag: internal error: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
