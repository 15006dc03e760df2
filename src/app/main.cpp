// main.cpp: the 'swarf' program: the command line (app/commands.h) and the exit codes
// (0 done, 1 an output that could not be written or an unexpected error, 2 bad input, 3 the simulation stopped, 130 /
// 143 interrupted by SIGINT / SIGTERM).
#include <fmt/format.h>

#include <CLI/CLI.hpp>

#include "app/build_info.h"
#include "app/commands.h"
#include "app/fp_traps.h"
#include "app/interrupt.h"
#include "io/console.h"
#include "swarf/core/errors.h"

int main(int argc, char** argv) {
  // Floating-point traps for tests (SWARF_FP_TRAPS=1, app/fp_traps.h); off in production runs.
  swarf::enable_fp_traps_from_env();
  CLI::App app{"swarf: DEM simulation of orthogonal metal cutting (bonded FCC workpiece, Bauschinger rods)"};
  app.require_subcommand(1);
  app.set_version_flag("--version", swarf::version_text());
  const auto commands = swarf::make_commands(app);
  // An unknown command gets its name said (CLI11 would say only that a subcommand is required).
  if (argc > 1 && argv[1][0] != '-') {
    std::string known;
    bool found = false;
    for (const CLI::App* sub : app.get_subcommands({})) {
      found = found || sub->get_name() == argv[1];
      known += (known.empty() ? "" : ", ") + sub->get_name();
    }
    if (!found) {
      swarf::eprint("swarf: error: unknown command '{}' (the commands: {}; swarf --help)\n", argv[1], known);
      return 2;
    }
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e);
  }
  try {
    for (const auto& c : commands)
      if (*c->sub) return c->run();
  } catch (const swarf::InputError& e) {
    swarf::eprint("swarf: error: {}\n", e.what());
    return 2;
  } catch (const swarf::Interrupted& e) {
    swarf::eprint("\nswarf: {}\n", e.what());
    return e.exit_code();
  } catch (const swarf::OutputError& e) {
    swarf::eprint("swarf: error: {}\n", e.what());
    return 1;
  } catch (const swarf::SimulationError& e) {
    swarf::eprint("swarf: simulation stopped: {}\n", e.what());
    return 3;
  } catch (const std::exception& e) {
    swarf::eprint("swarf: error: {}\n", e.what());
    return 1;
  }
  return 0;
}
