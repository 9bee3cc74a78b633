// rheomag: command-line entry point. Subcommands live in app/cmd_*.cpp.

#include <CLI/CLI.hpp>
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

}  // namespace rheomag::app

int main(int argc, char** argv) {
  CLI::App root{
      "rheomag: magnetorheological valve and damper design.\n"
      "Axisymmetric nonlinear magnetostatics (the FEMM step), MR-fluid gap flow, lumped "
      "dynamics,\nidentification, diagnosis and optimisation. Run 'rheomag COMMAND --help' "
      "for each command."};
  root.require_subcommand(1);
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
