// commands.h: the subcommands of 'swarf'. Each registers its options on the CLI11 app when
// made and runs when the command line selected it.
#pragma once

#include <CLI/CLI.hpp>
#include <memory>
#include <vector>

namespace swarf {

struct Command {
  virtual ~Command() = default;
  /// Runs the command; returns the exit code (errors are thrown: InputError 2, SimulationError 3).
  virtual int run() = 0;
  CLI::App* sub = nullptr;  ///< its subcommand: set when the command line selected it
};

/// Every subcommand, registered on 'app': lattice, rod, run, material, post, tool, bench, oxley, sweep, report, case keys.
std::vector<std::unique_ptr<Command>> make_commands(CLI::App& app);

}  // namespace swarf
