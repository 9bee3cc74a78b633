#pragma once
// Registry of CLI subcommands: each app/cmd_*.cpp registers itself at start-up.

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

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

}  // namespace rheomag::app
